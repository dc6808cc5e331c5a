# CLI tests of `assess run` (issue 5): the church example and bad input.
# Issue 41: the terminal prints the summary document, in Italian by default, English with --lang en.
assess_cli_test(run_church_text ARGS run mechanisms/church-facade.json --lang en
  PASS "Outcome of the checks.*Conclusion \\(adopted procedure: non-linear kinematic analysis \\(displacement\\), NTC 2018\\): SATISFIED, D/C = 0\\.991.*NTC 2018 +check at SLV, linear \\(strength\\), at ground +1\\.3410 +0\\.4322 +m/s² +3\\.102 +0\\.303 +not satisfied.*Safety indices.*Conclusions"
  FAIL_REGEX "VERIFICATO|Conclusione")
assess_cli_test(run_church_text_it ARGS run mechanisms/church-facade.json
  PASS "Esito delle verifiche.*Conclusione \\(procedura adottata: analisi cinematica non lineare \\(spostamento\\), NTC 2018\\): VERIFICATO, D/C = 0,991.*Indicatori di rischio.*Conclusioni"
  FAIL_REGEX "SATISFIED|Conclusion ")
assess_cli_test(run_church_json ARGS run mechanisms/church-facade.json --json
  PASS "\"checks\".*\"kind\": \"dynamic\".*\"comparison\".*\"dynamic\".*\"analyses\".*\"summary\".*\"kinematic\".*\"a0_star\"")
assess_cli_error_test(run_missing_record "/dynamic/records/1/file.*missing\\.AT2" run tests/cli/run_bad/missing_record.json)
assess_cli_test(run_keep_going ARGS run tests/cli/run_bad/missing_record.json --keep-going --lang en
  PASS "record skipped: /dynamic/records/1/file")
assess_cli_error_test(run_outside_grid "/site.*outside the NTC hazard grid" run tests/cli/run_bad/outside_grid.json)
assess_cli_error_test(run_no_site "/site: missing" run tests/cli/run_bad/no_site.json)
assess_cli_error_test(run_empty_records "/dynamic/records.*at least one record" run tests/cli/run_bad/empty_records.json)
assess_cli_error_test(run_restitution_2 "/dynamic/restitution/1.*\\[-1, 1\\]|/dynamic/restitution/1.*-1" run tests/cli/run_bad/restitution_2.json)
assess_cli_error_test(run_scale_string "/dynamic/records/1/scale" run tests/cli/run_bad/scale_string.json)
assess_cli_error_test(run_unknown_key "polarty.*polarity" run tests/cli/run_bad/unknown_key.json)

# The church HTML report in headless Chromium (7 plots, no console message):
# cli.report_church_it and cli.report_church_en (tests/cli/report.cmake).
# Issue 13: the dynamic analysis applies at height (floor motions) and to multi-block chains.
assess_cli_test(run_dynamic_at_height ARGS run tests/cli/run_bad/gable_dynamic.json --lang en
  PASS "check at SLV, non-linear dynamic, at height.*base at Z = 7\\.00 m,[ \n]floor motions a_Z = üg \\+ γ ψ ür \\(first mode: T1 = 0\\.215 s, ξ = 5 %, γ ψ = 1\\.2000\\)"
  FAIL_REGEX "not applicable")
assess_cli_test(run_dynamic_multi_block ARGS run tests/cli/run_bad/flexure_dynamic.json --lang en
  PASS "chain of 2 blocks.*q_u = 0\\.09827 rad"
  FAIL_REGEX "not applicable")
assess_cli_test(run_flexure_dynamic_json ARGS run mechanisms/vertical_flexure_dynamic.json --json
  PASS "\"d_control\".*\"d_star\".*\"impacts\".*\"overturned\".*\"theta_max\".*\"termination\".*\"kind\": \"chain\".*\"polarity\": \"both\"")
assess_cli_test(run_upper_storey_dynamic ARGS run mechanisms/upper_storey_dynamic.json --lang en
  PASS "check at SLV, non-linear dynamic, at height.*floor motions \\(first-mode filter\\)")
assess_cli_error_test(run_chain_two_sided "/dynamic/sidedness: \"two-sided\" needs a chain whose blocks and loads are mirror images"
  run tests/cli/run_bad/flexure_two_sided.json)
assess_cli_error_test(run_chain_housner "/dynamic/restitution: missing: a chain of several blocks needs a given coefficient"
  run tests/cli/run_bad/flexure_no_restitution.json)

# A case without a dynamic section: the report still loads, with its 4 figures
# (spectra, mechanism drawing, ADRS plot, D/C bars) and its verdict box.
add_test(NAME cli.run_kinematic_only_html_browser
  COMMAND sh -c "\"$1\" run mechanisms/free_wall_laquila.json --html \"$2\" > /dev/null && sh tests/browser/check_html.sh \"$2\" 4 \"class=.box verdict \""
          sh $<TARGET_FILE:assess_cli> ${CMAKE_CURRENT_BINARY_DIR}/free-wall-report.html
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.run_kinematic_only_html_browser PROPERTIES LABELS "cli;browser" SKIP_RETURN_CODE 77
  ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}")
# An explicit chain of three blocks (two columns and a beam) in `assess run`.
assess_cli_test(run_explicit_chain_dynamic ARGS run tests/data/chains/rocking_frame.json --lang en
  PASS "chain of 3 blocks.*q_u = 0\\.12435 rad"
  FAIL_REGEX "not applicable")
# Issue 21: records are never cut; the old trimming keys are refused with the key that replaces them.
assess_cli_error_test(run_whole_record_false "/dynamic/whole_record.*integrated to its last sample.*tail_s" run tests/cli/run_bad/whole_record_false.json)
assess_cli_error_test(run_free_tail_s "/dynamic/free_tail_s.*capped by \"tail_s\"" run tests/cli/run_bad/free_tail_s.json)
# Issue 24: the man page in UTF-8.
if(TARGET assess_man)
  add_test(NAME cli.man_page_utf8
    COMMAND ${CMAKE_COMMAND} -DMAN=${PROJECT_BINARY_DIR}/apps/assess.1 -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/man_page_utf8.cmake)
  set_tests_properties(cli.man_page_utf8 PROPERTIES LABELS cli)
endif()
# Issue 33: a roof thrust is integrated by the chain model (its moment exact at every rotation), the rocking
# laws' restitution computed from the block; horizontal flexure has no rocking equation (not applicable).
assess_cli_test(run_roof_thrust_dynamic ARGS run tests/cli/run_bad/roof_thrust_dynamic.json --lang en
  PASS "one-sided theory, chain model.*one-sided model of one body rotating about its ground hinge with the roof thrust's moment[ \n]exact")
assess_cli_test(run_horizontal_flexure_no_dynamics ARGS run tests/cli/run_bad/flexure_h_dynamic.json --lang en
  PASS "Not applicable: horizontal flexure: the strip is restored by the arch's thrust, not by gravity")

# Issue 41: no silent default that moves a verdict: a site needs its soil (it ran as soil A); a mistyped
# subcommand or option names the nearest one (before: "A subcommand is required", and for `run --htm r.html`
# a complaint that the case file r.html does not exist).
assess_cli_error_test(run_no_soil "no_soil.json: /site/soil: missing: the subsoil category of NTC 2018 Tab\\. 3\\.2\\.II"
  run tests/cli/run_bad/no_soil.json)
assess_cli_error_test(cli_typo_command "unknown command 'rnu' for `assess`; did you mean 'run'\\?"
  rnu mechanisms/church-facade.json)
assess_cli_error_test(cli_typo_option "unknown option --htm for `assess run`; did you mean --html\\?"
  run --htm r.html mechanisms/church-facade.json)
assess_cli_error_test(cli_typo_nested "unknown command 'selec' for `assess records`; did you mean 'select'\\?"
  records selec --lat 43.44 --lon 12.64)
