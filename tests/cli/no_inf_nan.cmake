# Issue 31: no report prints inf or nan. Every shipped example of mechanisms/
# (but the campaign) is run as text, --json and --html (or `assess kinematic`
# without a site), and each output is scanned (scripts/no_inf_nan.cmake).
# Release suite only: it reruns every example's whole assessment (the
# building and vertical flexure with dynamics take seconds each) to check the
# reports' text, which the sanitizer suite covers through the library paths
# of the other tests (docs/reliability.md, "CI time").
file(GLOB _shipped_examples CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/mechanisms/*.json)
foreach(_ex ${_shipped_examples})
  get_filename_component(_name ${_ex} NAME_WE)
  if(_name MATCHES "^campaign")
    continue()
  endif()
  add_test(NAME cli.no_inf_nan_${_name}
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:assess_cli> -DCASE=${_ex} -DWORK=${PROJECT_BINARY_DIR}/tests/no_inf_nan/${_name}
            -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/no_inf_nan.cmake
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(cli.no_inf_nan_${_name} PROPERTIES LABELS cli ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}"
    TIMEOUT 300)
endforeach()
