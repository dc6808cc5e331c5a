# CLI tests of `assess fragility` (issue 16).
set(_frag_case ${PROJECT_SOURCE_DIR}/tests/data/fragility/free_wall.json)
set(_frag_out ${PROJECT_BINARY_DIR}/tests/fragility_cli)

add_test(NAME cli.fragility_free_wall
  COMMAND ${CMAKE_COMMAND} -E env ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}
          sh -c "rm -rf '${_frag_out}/run' && '$<TARGET_FILE:assess_cli>' fragility '${_frag_case}' --stripes 72,475,2475 --records 3 --bootstrap 50 --out '${_frag_out}/run' --quiet")
set_tests_properties(cli.fragility_free_wall PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "stripes: 3 levels, 18 analyses \\(0 failed\\).*overturning: .*code: TR SLV 475 years.*report:  .*report.html")

add_test(NAME cli.fragility_json
  COMMAND ${CMAKE_COMMAND} -E env ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}
          sh -c "rm -rf '${_frag_out}/json' && '$<TARGET_FILE:assess_cli>' fragility '${_frag_case}' --stripes 72,475,2475 --records 3 --bootstrap 0 --no-plots --out '${_frag_out}/json' --quiet --json")
set_tests_properties(cli.fragility_json PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "\"code\": \\{.*\"SLV\".*\"curves\": \\[.*\"limit_state\": \"overturning\".*\"hazard_curve\"")

add_test(NAME cli.fragility_threads_identical
  COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:assess_cli> -DCOMMAND=fragility -DCAMPAIGN=${_frag_case} -DOUT=${_frag_out}/threads
          "-DFIRST_ARGS=--threads;1;--stripes;72,2475;--records;3;--bootstrap;0"
          "-DSECOND_ARGS=--threads;2;--stripes;72,2475;--records;3;--bootstrap;0"
          -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/campaign_compare.cmake)
set_tests_properties(cli.fragility_threads_identical PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "identical results.csv \\(13 lines\\)" ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}")

assess_cli_error_test(fragility_no_dynamic "no_dynamic.json: /dynamic: missing"
  fragility tests/data/fragility/no_dynamic.json --out ${_frag_out}/bad)
assess_cli_error_test(fragility_given_hazard "given_hazard.json: /site: .*given per limit state.*no hazard curve"
  fragility tests/data/fragility/given_hazard.json --out ${_frag_out}/bad)
assess_cli_error_test(fragility_listed_stripes "listed_records.json: /dynamic/records: a multiple-stripe analysis.*--ida"
  fragility tests/data/fragility/listed_records.json --out ${_frag_out}/bad)
assess_cli_error_test(fragility_bad_stripe "--stripes: item 2: expected a number, got 'abc' \\(a comma-separated list of numbers in years\\)"
  fragility tests/data/fragility/free_wall.json --stripes 30,abc --out ${_frag_out}/bad)
assess_cli_error_test(fragility_stripe_range "--stripes: item 1: value 10 out of range: expected in \\[30, 2475\\] years"
  fragility tests/data/fragility/free_wall.json --stripes 10 --out ${_frag_out}/bad)

# The HTML page loads in headless Chromium with its 3 plots (fragility,
# hazard, integrand of the governing fitted curve) and no console error.
add_test(NAME cli.fragility_html_browser
  COMMAND sh -c "rm -rf \"$2\" && \"$1\" fragility tests/data/fragility/free_wall.json --stripes 72,475,2475 --records 3 --bootstrap 20 --out \"$2\" --quiet > /dev/null && sh tests/browser/check_html.sh \"$2/report.html\" 3"
          sh $<TARGET_FILE:assess_cli> ${_frag_out}/html
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.fragility_html_browser PROPERTIES LABELS "cli;browser" SKIP_RETURN_CODE 77
  ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}")

# With MPI: 2 ranks write the same results.csv as one process.
find_program(ASSESS_MPIRUN mpirun)
get_target_property(_assess_cli_defs assess_cli COMPILE_DEFINITIONS)
if(ASSESS_MPIRUN AND "ASSESS_HAVE_MPI=1" IN_LIST _assess_cli_defs)
  add_test(NAME cli.fragility_mpi_identical
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:assess_cli> -DCOMMAND=fragility -DCAMPAIGN=${_frag_case} -DOUT=${_frag_out}/mpi
            "-DSECOND=${ASSESS_MPIRUN};--allow-run-as-root;--oversubscribe;-np;2"
            "-DFIRST_ARGS=--stripes;72,2475;--records;3;--bootstrap;0"
            "-DSECOND_ARGS=--stripes;72,2475;--records;3;--bootstrap;0"
            -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/campaign_compare.cmake)
  set_tests_properties(cli.fragility_mpi_identical PROPERTIES LABELS cli
    PASS_REGULAR_EXPRESSION "run on 2 MPI ranks.*identical results.csv \\(13 lines\\)" ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}"
    ENVIRONMENT_MODIFICATION "${ASSESS_MPI_TEST_ENV}")
endif()

# `assess run --fragility DIR` adds the fragility line; a fragility of another case is refused.
add_test(NAME cli.fragility_in_run
  COMMAND ${CMAKE_COMMAND} -E env ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}
          sh -c "rm -rf '${_frag_out}/inrun' && '$<TARGET_FILE:assess_cli>' fragility '${_frag_case}' --stripes 72,475,2475 --records 3 --bootstrap 0 --no-plots --out '${_frag_out}/inrun' --quiet > /dev/null && '$<TARGET_FILE:assess_cli>' run '${_frag_case}' --fragility '${_frag_out}/inrun' --lang en"
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.fragility_in_run PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "Additional probabilistic result: annual risk of overturning.*Not a code check.*years")
assess_cli_error_test(fragility_in_run_other_case "summary.json.*belongs to another case"
  run mechanisms/free_wall_laquila.json --fragility ${_frag_out}/inrun)
set_tests_properties(cli.fragility_in_run_other_case PROPERTIES DEPENDS cli.fragility_in_run)

# Chains and mechanisms at height (the dynamic model of `assess run`,
# assessment/mechanism_dynamics): a 2-block chain at Z = 3 m (floor motions)
# and a one-body mechanism at Z = 4 m run end to end; 2 stripes x 2 records x
# 2 polarities x 2 restitution values = 16 analyses each.
add_test(NAME cli.fragility_chain
  COMMAND ${CMAKE_COMMAND} -E env ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}
          sh -c "rm -rf '${_frag_out}/chain' && '$<TARGET_FILE:assess_cli>' fragility mechanisms/vertical_flexure_dynamic.json --stripes 475,2475 --records 2 --bootstrap 0 --no-plots --out '${_frag_out}/chain' --quiet"
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.fragility_chain PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "model: one-sided chain of 2 blocks.*base at Z = 3.00 m, floor motions a_Z.*stripes: 2 levels, 16 analyses \\(0 failed\\).*restitution e = -0.5:.*restitution e = 0:.*report:  .*report.html")
add_test(NAME cli.fragility_at_height
  COMMAND ${CMAKE_COMMAND} -E env ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}
          sh -c "rm -rf '${_frag_out}/height' && '$<TARGET_FILE:assess_cli>' fragility mechanisms/upper_storey_dynamic.json --stripes 475,2475 --records 2 --bootstrap 0 --no-plots --out '${_frag_out}/height' --quiet --json"
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.fragility_at_height PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "\"analyses\": 16,.*\"failed\": 0,.*\"model\": \"one body rotating about its ground hinge \\(rocking model, seed Eq. 1\\); base at Z = 4.00 m, floor motions a_Z")
add_test(NAME cli.fragility_chain_threads_identical
  COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:assess_cli> -DCOMMAND=fragility
          -DCAMPAIGN=${PROJECT_SOURCE_DIR}/mechanisms/vertical_flexure_dynamic.json -DOUT=${_frag_out}/chain_threads
          "-DFIRST_ARGS=--threads;1;--stripes;475,2475;--records;2;--bootstrap;0"
          "-DSECOND_ARGS=--threads;2;--stripes;475,2475;--records;2;--bootstrap;0"
          -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/campaign_compare.cmake)
set_tests_properties(cli.fragility_chain_threads_identical PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "identical results.csv \\(17 lines\\)" ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}")
# Refusals (exit status 2): a chain the dynamic model cannot represent
# (interlocking friction), floor motions given by the user (no hazard curve),
# a mechanism at height without the building.
assess_cli_error_test(fragility_friction_refused
  "friction_block.json: /mechanism: the dynamic model does not apply to the governing mechanism.*interlocking friction"
  fragility tests/data/fragility/friction_block.json --stripes 475,975 --out ${_frag_out}/bad)
assess_cli_error_test(fragility_floor_input_refused
  "floor_input.json: /dynamic/input: \"floor\": a fragility scales ground records.*no hazard curve"
  fragility tests/data/fragility/floor_input.json --ida --out ${_frag_out}/bad)
assess_cli_error_test(fragility_height_no_building "height_no_building.json: /building: missing"
  fragility tests/data/fragility/height_no_building.json --out ${_frag_out}/bad)

# `assess run --fragility DIR` (issue 16): the additional probabilistic result
# in the JSON ("fragility": median, beta, lambda_c, return period, P in VN, TR
# of SLV; equal to summary.json and to their closed forms) and in the HTML
# relazione (IT and EN box after the verdicts by approach, labelled as not a
# code check); the terminal within 120 columns.
find_program(ASSESS_PYTHON3 python3)
if(ASSESS_PYTHON3)
  add_test(NAME cli.fragility_in_run_report
    COMMAND ${ASSESS_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/check_fragility_in_report.py
            $<TARGET_FILE:assess_cli> tests/data/fragility/free_wall.json ${_frag_out}/in_report
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(cli.fragility_in_run_report PROPERTIES LABELS cli
    PASS_REGULAR_EXPRESSION "fragility in report: .*: ok" ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}")
endif()
