# CLI tests of issue 10 (reliability): hostile input is a named error with a
# non-zero exit, never a crash, an internal error or an absurd number.
set(_rel_block --thickness 0.25 --height 3 --unit-weight 12.06)
set(_rel_stu spectra/records/RSN292_ITALY_A-STU270.AT2)

# Defects 1, 2, 7: record files.
assess_cli_error_test(rel_npts_digits "npts_digits.AT2: header field NPTS: 9+\\.\\.\\. points is more than the limit"
  rocking --model rigid ${_rel_block} --record tests/data/hostile/npts_digits.AT2)
assess_cli_error_test(rel_separators "separators.txt:1: no value on this line"
  rocking --model rigid ${_rel_block} --record tests/data/hostile/separators.txt --dt 0.01)
assess_cli_error_test(rel_inf_g "inf_g.txt:2: value overflows once converted to m/s\\^2"
  rocking --model rigid ${_rel_block} --record tests/data/hostile/inf_g.txt --dt 0.01 --unit g)
# Defect 5: JSON number overflow, with the file and the JSON path.
assess_cli_error_test(rel_json_overflow "height_overflow.json: /mechanism/storeys/0/height: number out of the range of a double"
  kinematic tests/data/hostile/height_overflow.json)
# Defect 6: k beyond what the integration resolves, from the CLI and a case file.
assess_cli_error_test(rel_k_huge_cli "--k must lie in \\[0, 1e\\+09\\] kN/m\\^3"
  rocking --model smooth ${_rel_block} --k 1e20 --record ${_rel_stu})
assess_cli_error_test(rel_k_huge_run "k_huge.json: /dynamic/k: value 1e\\+20 out of range"
  run tests/data/hostile/k_huge.json)
# Defect 11: the same bounds as the case file.
assess_cli_error_test(rel_tail "--tail must lie in \\[0, 600\\] s, got 1e\\+09"
  rocking --model rigid ${_rel_block} --record ${_rel_stu} --tail 1e9)
assess_cli_error_test(rel_rtol "--rtol must lie in \\[1e-14, 0\\.01\\]"
  rocking --model rigid ${_rel_block} --record ${_rel_stu} --rtol 10)
# Defect 12: --dt nan is an error, not "no --dt"; a directory is not a format.
assess_cli_error_test(rel_dt_nan "--dt: time step must be positive \\(s\\), got not-a-number"
  rocking --model rigid ${_rel_block} --record tests/data/rocking_plain_1col.txt --dt nan)
assess_cli_error_test(rel_directory "tests/data: is a directory, expected a record file"
  rocking --model rigid ${_rel_block} --record tests/data)
# Defect 8: --limit 0 ran everything.
assess_cli_error_test(rel_limit_zero "--limit 0 would run no analysis"
  campaign tests/data/campaign/tiny.json --out ${PROJECT_BINARY_DIR}/tests/rel_limit0 --limit 0)
# Defect 9: a second writer on one --out is refused (flock(1) holds the lock
# as a concurrent campaign would).
set(_rel_lock_out ${PROJECT_BINARY_DIR}/tests/rel_locked)
add_test(NAME cli.rel_locked_out
  COMMAND ${CMAKE_COMMAND} -DEXE=sh
          "-DARGS=-c;rm -rf '${_rel_lock_out}' && mkdir -p '${_rel_lock_out}' && flock '${_rel_lock_out}/.assess-lock' '$<TARGET_FILE:assess_cli>' campaign tests/data/campaign/tiny.json --out '${_rel_lock_out}' --quiet"
          "-DREGEX=output directory '.*rel_locked' is in use by another assess campaign"
          -P ${CMAKE_CURRENT_SOURCE_DIR}/support/expect_error.cmake
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.rel_locked_out PROPERTIES LABELS cli ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}")
