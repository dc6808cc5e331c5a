# CLI tests of `assess campaign` (issue 6).
set(_campaign_tiny ${PROJECT_SOURCE_DIR}/tests/data/campaign/tiny.json)
set(_campaign_out ${PROJECT_BINARY_DIR}/tests/campaign_cli)

add_test(NAME cli.campaign_tiny_run
  COMMAND ${CMAKE_COMMAND} -E env ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}
          sh -c "rm -rf '${_campaign_out}/run' && '$<TARGET_FILE:assess_cli>' campaign '${_campaign_tiny}' --out '${_campaign_out}/run' --threads 2")
set_tests_properties(cli.campaign_tiny_run PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "48 analyses \\(0 resumed, 48 run in [0-9.]+ s, 0 failed\\).*summary.json.*fig4a_w1.svg.*fig4b_capacity.svg.*fig5a_strength.svg.*fig5b_displacement.svg")

add_test(NAME cli.campaign_threads_identical
  COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:assess_cli> -DCAMPAIGN=${_campaign_tiny} -DOUT=${_campaign_out}/threads
          "-DFIRST_ARGS=--threads;1" "-DSECOND_ARGS=--threads;2"
          -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/campaign_compare.cmake)
set_tests_properties(cli.campaign_threads_identical PROPERTIES LABELS cli PASS_REGULAR_EXPRESSION "identical results.csv \\(49 lines\\)")

assess_cli_error_test(campaign_missing_record "/records/1/file: record file 'no_such_record.AT2' not found"
  campaign tests/data/campaign/missing_record.json --out ${_campaign_out}/missing)
assess_cli_error_test(campaign_no_file "nonexistent.json: cannot open the campaign file: No such file" campaign tests/data/campaign/nonexistent.json --out ${_campaign_out}/none)

# With MPI: 2 ranks on one machine write the same results.csv as one process.
# (Registered only when assess was built with MPI and mpirun exists; as root,
# Open MPI needs --allow-run-as-root, and --oversubscribe on a 2-core machine.)
find_program(ASSESS_MPIRUN mpirun)
get_target_property(_assess_cli_defs assess_cli COMPILE_DEFINITIONS)
if(ASSESS_MPIRUN AND "ASSESS_HAVE_MPI=1" IN_LIST _assess_cli_defs)
  add_test(NAME cli.campaign_mpi_identical
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:assess_cli> -DCAMPAIGN=${_campaign_tiny} -DOUT=${_campaign_out}/mpi
            "-DSECOND=${ASSESS_MPIRUN};--allow-run-as-root;--oversubscribe;-np;2"
            -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/campaign_compare.cmake)
  set_tests_properties(cli.campaign_mpi_identical PROPERTIES LABELS cli PASS_REGULAR_EXPRESSION "on 2 MPI ranks.*identical results.csv \\(49 lines\\)"
    ENVIRONMENT_MODIFICATION "${ASSESS_MPI_TEST_ENV}")
endif()

# Unperturbed campaign rows equal single `assess rocking` runs.
add_test(NAME cli.campaign_rows_vs_rocking
  COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:assess_cli> -DSRC=${PROJECT_SOURCE_DIR} -DOUT=${_campaign_out}/vs_rocking
          -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/campaign_vs_rocking.cmake)
set_tests_properties(cli.campaign_rows_vs_rocking PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "smooth: theta_max .* as assess rocking.*rigid: theta_max .* as assess rocking")
