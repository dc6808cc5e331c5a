# CLI tests of `assess run` (issue 5): the church example and bad input.
assess_cli_test(run_church_text ARGS run mechanisms/church-facade.json
  PASS "a0\\* = alpha0 g/\\(e\\* FC\\).*0\\.432.*NTC2008  SLV  strength.*1\\.3409.*non verificato / not satisfied.*dynamic")
assess_cli_test(run_church_json ARGS run mechanisms/church-facade.json --json
  PASS "\"checks\".*\"kind\": \"dynamic\".*\"comparison\".*\"dynamic\".*\"analyses\".*\"summary\".*\"kinematic\".*\"a0_star\"")
assess_cli_error_test(run_missing_record "/dynamic/records/1/file.*missing\\.AT2" run tests/cli/run_bad/missing_record.json)
assess_cli_test(run_keep_going ARGS run tests/cli/run_bad/missing_record.json --keep-going
  PASS "record skipped: /dynamic/records/1/file")
assess_cli_error_test(run_outside_grid "/site.*outside the NTC hazard grid" run tests/cli/run_bad/outside_grid.json)
assess_cli_error_test(run_no_site "/site: missing" run tests/cli/run_bad/no_site.json)
assess_cli_error_test(run_empty_records "/dynamic/records.*at least one record" run tests/cli/run_bad/empty_records.json)
assess_cli_error_test(run_restitution_2 "/dynamic/restitution/1.*\\[-1, 1\\]|/dynamic/restitution/1.*-1" run tests/cli/run_bad/restitution_2.json)
assess_cli_error_test(run_scale_string "/dynamic/records/1/scale" run tests/cli/run_bad/scale_string.json)
assess_cli_error_test(run_unknown_key "polarty.*polarity" run tests/cli/run_bad/unknown_key.json)

# The HTML report loads in headless Chromium with every plot and no console
# error (skipped, exit 77, when chromium is not installed).
add_test(NAME cli.run_church_html_browser
  COMMAND sh -c "\"$1\" run mechanisms/church-facade.json --html \"$2\" > /dev/null && sh tests/browser/check_html.sh \"$2\" 7 \"class=.verdict \""
          sh $<TARGET_FILE:assess_cli> ${CMAKE_CURRENT_BINARY_DIR}/church-report.html
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.run_church_html_browser PROPERTIES LABELS "cli;browser" SKIP_RETURN_CODE 77
  ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}")
assess_cli_test(run_dynamic_at_height ARGS run tests/cli/run_bad/gable_dynamic.json
  PASS "not applicable: the governing mechanism is at height")
assess_cli_test(run_dynamic_multi_block ARGS run tests/cli/run_bad/flexure_dynamic.json
  PASS "not applicable: .*multi-block chains")

# A case without a dynamic section: the report still loads, with its 4 figures
# (spectra, mechanism drawing, ADRS plot, D/C bars) and its verdict box.
add_test(NAME cli.run_kinematic_only_html_browser
  COMMAND sh -c "\"$1\" run mechanisms/free_wall_laquila.json --html \"$2\" > /dev/null && sh tests/browser/check_html.sh \"$2\" 4 \"class=.verdict \""
          sh $<TARGET_FILE:assess_cli> ${CMAKE_CURRENT_BINARY_DIR}/free-wall-report.html
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.run_kinematic_only_html_browser PROPERTIES LABELS "cli;browser" SKIP_RETURN_CODE 77
  ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}")
