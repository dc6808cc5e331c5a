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
assess_cli_error_test(rel_dt_nan "--dt: must be a finite number, got 'nan'"
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

# ---- Issue 31: hostile input, round four (docs/reliability.md, "Round four") ----
# A shell script `SCRIPT` (with @EXE@ for the tool) that must exit non-zero and
# print REGEX; expect_error.cmake also refuses inf, nan, "internal error" and
# a crash in its output. EXIT: the exit status it must have (2 or 1).
function(rel4_sh_test name exit regex script)
  string(REPLACE "@EXE@" "'$<TARGET_FILE:assess_cli>'" script "${script}")
  # The script goes to a file: its ';' would split the command's argument list.
  file(GENERATE OUTPUT ${PROJECT_BINARY_DIR}/tests/round4_scripts/${name}.sh CONTENT "${script}\n")
  add_test(NAME cli.${name}
    COMMAND ${CMAKE_COMMAND} -DEXE=sh "-DARGS=${PROJECT_BINARY_DIR}/tests/round4_scripts/${name}.sh" "-DREGEX=${regex}"
            -DEXIT=${exit} -P ${CMAKE_CURRENT_SOURCE_DIR}/support/expect_error.cmake
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(cli.${name} PROPERTIES LABELS cli ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}" TIMEOUT 60)
endfunction()
set(_r4 ${PROJECT_BINARY_DIR}/tests/round4)

# Class 1, the bounded reader: /dev/zero as a record, a listed record, the
# hazard grid, a record catalogue, a case and a campaign; a directory as the
# catalogue ("internal error: basic_filebuf::underflow"). Each was read until
# memory ran out (2 GB in 15 s) or was an internal error.
assess_cli_error_test(rel4_zero_record "/dev/zero: is a character device, expected a record file \\(a regular file\\)"
  rocking --model rigid ${_rel_block} --record /dev/zero)
assess_cli_error_test(rel4_zero_plain_record "/dev/zero: is a character device, expected a record file"
  rocking --model rigid ${_rel_block} --record /dev/zero --dt 0.01)
assess_cli_error_test(rel4_zero_listed_record "listed_dev_zero.json: /dynamic/records/0/file: /dev/zero: is a character device, expected a record file"
  run tests/data/hostile/listed_dev_zero.json)
assess_cli_error_test(rel4_zero_grid "/dev/zero: is a character device, expected a hazard grid file"
  spectrum --lat 42.35 --lon 13.4 --grid /dev/zero)
assess_cli_error_test(rel4_zero_catalogue "/dev/zero: is a character device, expected a record catalogue"
  records list --catalogue /dev/zero)
assess_cli_error_test(rel4_dir_catalogue "tests/data: is a directory, expected a record catalogue"
  records list --catalogue tests/data)
assess_cli_error_test(rel4_zero_case "/dev/zero: is a character device, expected a case file" run /dev/zero)
assess_cli_error_test(rel4_zero_campaign "/dev/zero: is a character device, expected a campaign file"
  campaign /dev/zero --out ${_r4}/zero_campaign)
rel4_sh_test(rel4_fifo_case 2 "fifo: is a FIFO \\(named pipe\\), expected a case file"
  "rm -rf '${_r4}/fifo' && mkdir -p '${_r4}/fifo' && mkfifo '${_r4}/fifo/fifo' && @EXE@ kinematic '${_r4}/fifo/fifo'")
# Class 1, a depth limit in every JSON parse: a building nested 100 000 levels
# deep in an object, the project, an analysis array (SIGSEGV).
foreach(_where project analysis walls)
  add_test(NAME cli.rel4_deep_building_${_where}
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:assess_cli> -DWHERE=${_where} -DWORK=${_r4}/deep_${_where}
            -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/deep_building.cmake
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(cli.rel4_deep_building_${_where} PROPERTIES LABELS cli TIMEOUT 60
    ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}"
    PASS_REGULAR_EXPRESSION "deep.json: /${_where}/a/a/a[^\n]*nested more than 64 levels deep")
endforeach()
# Class 1, the numeric rules: coordinates of 1e150 m ("free(): invalid
# pointer"), a subnormal time step, a hexadecimal value, a tie spacing of
# 1e-300 m in a building (with the building path and the mechanism id).
assess_cli_error_test(rel4_coordinates_1e150 "block_1e150.json: /mechanism/blocks/0/polygon/0/0: value -1e\\+150 out of range: expected in \\[-1000, 1000\\] m"
  kinematic tests/data/hostile/block_1e150.json)
assess_cli_error_test(rel4_dt_subnormal "dt_subnormal.AT2: the header gives the time step 9.99989e-321 s: expected a time step in \\[1e-06, 10\\] s"
  rocking --model rigid ${_rel_block} --record tests/data/hostile/dt_subnormal.AT2)
assess_cli_error_test(rel4_hex_value "hex_value.txt:2: hexadecimal value '0x1p-3'"
  rocking --model rigid ${_rel_block} --record tests/data/hostile/hex_value.txt --dt 0.01)
assess_cli_error_test(rel4_building_tie_spacing "building_tie_spacing.json: /walls/0/mechanisms/1/ties/0/spacing_m: value 1e-300 out of range: expected in \\[0\\.1, 500\\] m.*\\[M2 "
  run tests/data/hostile/building_tie_spacing.json)
assess_cli_error_test(rel4_bow_tie "bow_tie_block.json: /mechanism/blocks/0/polygon: its edges cross"
  kinematic tests/data/hostile/bow_tie_block.json)
assess_cli_error_test(rel4_control_character "ctrl_name.json: /mechanism/blocks/0/name: the text holds a control character \\(U\\+0000\\)"
  kinematic tests/data/hostile/ctrl_name.json)
# Class 2, outputs: --html naming the case, --expand DIR holding the building
# file, a link out of DIR, --history on a full disk (exit 1, not 0), --out
# onto a regular file; the input stays byte for byte.
rel4_sh_test(rel4_html_onto_case 2 "--html: .*case.json is an input of this run: refusing to replace it.*input unchanged"
  "rm -rf '${_r4}/html' && mkdir -p '${_r4}/html' && cp mechanisms/two_storey_facade.json '${_r4}/html/case.json' && cp '${_r4}/html/case.json' '${_r4}/html/orig' && @EXE@ run '${_r4}/html/case.json' --html '${_r4}/html/case.json'; rc=$?; test \"$(cksum < '${_r4}/html/case.json')\" = \"$(cksum < '${_r4}/html/orig')\" && echo input unchanged >&2; exit $rc")
rel4_sh_test(rel4_expand_onto_building 2 "--expand .*M1.json is an input of this run: refusing to replace it.*input unchanged"
  "rm -rf '${_r4}/expand' && mkdir -p '${_r4}/expand' && cp tests/cli/building/palazzo_sulmona.json '${_r4}/expand/M1.json' && cp '${_r4}/expand/M1.json' '${_r4}/orig.json' && @EXE@ run '${_r4}/expand/M1.json' --expand '${_r4}/expand'; rc=$?; test \"$(cksum < '${_r4}/expand/M1.json')\" = \"$(cksum < '${_r4}/orig.json')\" && echo input unchanged >&2; exit $rc")
rel4_sh_test(rel4_expand_link_out 2 "M1.json is a symbolic link to .*outside/M1.json, outside .*nothing written outside"
  "rm -rf '${_r4}/link' && mkdir -p '${_r4}/link/dir' '${_r4}/link/outside' && ln -s '${_r4}/link/outside/M1.json' '${_r4}/link/dir/M1.json' && @EXE@ run tests/cli/building/palazzo_sulmona.json --expand '${_r4}/link/dir'; rc=$?; test -e '${_r4}/link/outside/M1.json' || echo nothing written outside >&2; exit $rc")
assess_cli_error_test(rel4_history_full_disk "--history: /dev/full: cannot write: No space left on device"
  rocking --model rigid ${_rel_block} --record ${_rel_stu} --history /dev/full)
set_tests_properties(cli.rel4_history_full_disk PROPERTIES ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}")
rel4_sh_test(rel4_history_full_disk_exit1 1 "No space left on device"
  "@EXE@ rocking --model rigid --thickness 0.25 --height 3 --unit-weight 12.06 --record ${_rel_stu} --history /dev/full")
rel4_sh_test(rel4_out_regular_file 2 "--out: .*afile: is a regular file, expected a folder"
  "mkdir -p '${_r4}' && : > '${_r4}/afile' && @EXE@ campaign tests/data/campaign/tiny.json --out '${_r4}/afile' --quiet")
# Class 3, messages and options: --k nan, --mechanism by id, --expand with
# --mechanism honoured, comuni, TR / VN / damping of 1e308, an empty period list.
assess_cli_error_test(rel4_k_nan "--k: must be a finite number, got 'nan'"
  rocking --model smooth ${_rel_block} --k nan --record ${_rel_stu})
assess_cli_error_test(rel4_scale_inf "--scale: must be a finite number, got 'inf'"
  rocking --model rigid ${_rel_block} --scale inf --record ${_rel_stu})
assess_cli_error_test(rel4_thickness_hex "--thickness: must be a decimal number, got '0x1p-2'"
  rocking --model rigid --thickness 0x1p-2 --height 3 --unit-weight 12 --record ${_rel_stu})
assess_cli_error_test(rel4_mechanism_name_as_id "building_name_id.json: /walls/0/mechanisms/0/name: \"M2\" reads as the id of another mechanism"
  run tests/data/hostile/building_name_id.json --mechanism M2)
rel4_sh_test(rel4_expand_with_mechanism 3 "expanded case written to .*/M2.json.*only M2.json"
  "rm -rf '${_r4}/exp1' && @EXE@ run tests/cli/building/palazzo_sulmona.json --mechanism M2 --expand '${_r4}/exp1' >'${_r4}/exp1.out' 2>/dev/null; cat '${_r4}/exp1.out' | tail -2; test \"$(ls '${_r4}/exp1')\" = M2.json && echo only M2.json; exit 3")
assess_cli_error_test(rel4_comune_emoji "--comune: comune 'L'Aquila.*' is not in the ISTAT list"
  spectrum --comune "L'Aquila😀")
assess_cli_error_test(rel4_comune_part_of_another "comune 'Cavallino' is ambiguous: Cavallino \\(LE\\).*Cavallino-Treporti \\(VE\\)"
  spectrum --comune Cavallino)
assess_cli_error_test(rel4_tr_huge "--tr: value 1e\\+308 out of range: expected in \\[1, 1e\\+06\\] years"
  spectrum --lat 42.35 --lon 13.4 --tr 1e308)
assess_cli_error_test(rel4_vn_huge "--vn: value 1e\\+308 out of range: expected in \\[1, 10000\\] years"
  spectrum --lat 42.35 --lon 13.4 --vn 1e308)
assess_cli_error_test(rel4_damping_huge "--damping: value 1e\\+308 out of range: expected in \\[0, 100\\] %"
  spectrum --lat 42.35 --lon 13.4 --damping 1e308)
assess_cli_error_test(rel4_empty_periods "--periods ', ,': expected a comma-separated list of periods"
  spectrum --lat 42.35 --lon 13.4 --periods ", ,")
assess_cli_error_test(rel4_empty_periods_blank "--periods: 1 required TEXT missing"
  spectrum --lat 42.35 --lon 13.4 --periods "")
# Chatter: a record scaled by 1e-13 made the smooth two-sided block cross
# theta = 0 ten million times (6 s per analysis) before failing; the event
# bound of analysis_limits.hpp ends it in milliseconds, as a failed row.
add_test(NAME cli.rel4_campaign_tiny_scale
  COMMAND sh -c "rm -rf '${_r4}/tiny_scale' && '$<TARGET_FILE:assess_cli>' campaign tests/data/hostile/campaign_tiny_scale.json --out '${_r4}/tiny_scale' --quiet --no-plots && grep -o 'events accumulate' '${_r4}/tiny_scale/results.csv'"
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.rel4_campaign_tiny_scale PROPERTIES LABELS cli TIMEOUT 20
  ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}"
  PASS_REGULAR_EXPRESSION "1 analyses \\(0 resumed, 1 run in [0-9.]+ s, 1 failed\\).*events accumulate")
# A fragility --resume into the output of another case with the same file
# name (another folder): its content differs, so the inputs do (issue 31).
rel4_sh_test(rel4_fragility_resume_other_case 2 "cannot resume into .*its fragility.json describes a different campaign or fragility study"
  "rm -rf '${_r4}/frag' && mkdir -p '${_r4}/frag/a' '${_r4}/frag/b' && cp tests/data/fragility/free_wall.json '${_r4}/frag/a/case.json' && sed 's/\"thickness\": *0.5/\"thickness\": 0.55/' tests/data/fragility/free_wall.json > '${_r4}/frag/b/case.json' && cd '${_r4}/frag/a' && @EXE@ fragility case.json --stripes 475 --records 3 --bootstrap 0 --out ../out --quiet --no-plots --json > /dev/null && cd ../b && @EXE@ fragility case.json --stripes 475 --records 3 --bootstrap 0 --out ../out --resume --quiet --no-plots")
