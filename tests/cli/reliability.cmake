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
assess_cli_error_test(rel_k_huge_cli "--k: value 1e\\+20 out of range: expected in \\(0, 1e\\+09\\] kN/m\\^3 \\(a stiffer base is the rigid model"
  rocking --model smooth ${_rel_block} --k 1e20 --record ${_rel_stu})
assess_cli_error_test(rel_k_huge_run "k_huge.json: /dynamic/k: value 1e\\+20 out of range"
  run tests/data/hostile/k_huge.json)
# Defect 11: the same bounds as the case file.
assess_cli_error_test(rel_tail "--tail: value 1e\\+09 out of range: expected in \\[0, 600\\] s"
  rocking --model rigid ${_rel_block} --record ${_rel_stu} --tail 1e9)
assess_cli_error_test(rel_rtol "--rtol: value 10 out of range: expected in \\[1e-14, 0\\.01\\]"
  rocking --model rigid ${_rel_block} --record ${_rel_stu} --rtol 10)
# Defect 12: --dt nan is an error, not "no --dt"; a directory is not a format.
assess_cli_error_test(rel_dt_nan "--dt: must be a finite number, got 'nan'"
  rocking --model rigid ${_rel_block} --record tests/data/rocking_plain_1col.txt --dt nan)
assess_cli_error_test(rel_directory "tests/data: is a directory, expected a record file"
  rocking --model rigid ${_rel_block} --record tests/data)
# Defect 8: --limit 0 ran everything.
assess_cli_error_test(rel_limit_zero "--limit: value 0 out of range: expected in \\[1, 1e\\+18\\] analyses \\(only the analyses with id < N run: 0 would run none\\)"
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

# ---- Issue 39: hostile input, round five (docs/reliability.md, "Round five") ----
set(_r5 ${PROJECT_BINARY_DIR}/tests/round5)
file(MAKE_DIRECTORY ${_r5}/meta)
# A copy of the small library (tests/data/records_mini) with its records in
# DIR, built by `assess records build` there: the shell lines of the tests below.
set(_r5_lib "mkdir -p DIR && cp spectra/records/elCentro.AT2 spectra/records/ARL360.at2 spectra/records/RSN289_1.AT2 DIR/ && grep -v FEMA tests/data/records_mini/metadata.csv | sed 's#../../../spectra/records/##' > DIR/metadata.csv && @EXE@ records build --metadata DIR/metadata.csv > /dev/null")

# Class 1, no exception through std::call_once (SIGABRT before): records
# changed since the build, seen by `run` (the selection's records), `records
# show` and `fragility`; a window the wrong way round named as the options'.
string(REPLACE "DIR" "${_r5}/changed" _r5_changed "${_r5_lib}")
rel4_sh_test(rel5_changed_record_run 2 "select_local_catalogue.json: /dynamic/select: catalogue record [A-Za-z0-9_]+\\.(AT2|at2): .*the file changed since the catalogue was built"
  "rm -rf '${_r5}/changed' && ${_r5_changed} && for f in '${_r5}'/changed/*.[Aa][Tt]2; do echo ' ' >> \"$f\"; done && cp tests/data/hostile/select_local_catalogue.json '${_r5}/changed/' && @EXE@ run '${_r5}/changed/select_local_catalogue.json'")
string(REPLACE "DIR" "${_r5}/changed_show" _r5_changed_show "${_r5_lib}")
rel4_sh_test(rel5_changed_record_show 2 "ARL360.at2: the file changed since the catalogue was built \\(content hash [0-9a-f]+, catalogue [0-9a-f]+\\): run `assess records build`"
  "rm -rf '${_r5}/changed_show' && ${_r5_changed_show} && echo ' ' >> '${_r5}/changed_show/ARL360.at2' && @EXE@ records show ARL360 --catalogue '${_r5}/changed_show/catalogue.json'")
string(REPLACE "DIR" "${_r5}/changed_frag" _r5_changed_frag "${_r5_lib}")
rel4_sh_test(rel5_changed_record_fragility 2 "the file changed since the catalogue was built"
  "rm -rf '${_r5}/changed_frag' && ${_r5_changed_frag} && for f in '${_r5}'/changed_frag/*.[Aa][Tt]2; do echo ' ' >> \"$f\"; done && cp tests/data/hostile/select_local_catalogue.json '${_r5}/changed_frag/' && @EXE@ fragility '${_r5}/changed_frag/select_local_catalogue.json' --stripes 475 --bootstrap 0 --out '${_r5}/changed_frag/out' --quiet --no-plots")
assess_cli_error_test(rel5_select_mw_reversed "--mw-min 7 is above --mw-max 5: expected a window with min <= max"
  records select --lat 43.44 --lon 12.64 --mw-min 7 --mw-max 5)
# Class 2, the bounded reader for the record library: the catalogue a
# directory (internal error before), /dev/zero (exit 1, out of memory), a
# record that is a FIFO (a hang).
assess_cli_error_test(rel5_select_catalogue_dir "tests/data: is a directory, expected a record catalogue"
  records select --ag 0.25 --F0 2.4 --Tc-star 0.3 --catalogue tests/data)
rel4_sh_test(rel5_select_catalogue_dev_zero 2 "/dev/zero: is a character device, expected a record catalogue"
  "@EXE@ records select --ag 0.25 --F0 2.4 --Tc-star 0.3 --catalogue /dev/zero")
string(REPLACE "DIR" "${_r5}/fifo" _r5_fifo "${_r5_lib}")
rel4_sh_test(rel5_record_fifo 2 "ARL360.at2: is a FIFO \\(named pipe\\), expected a record file"
  "rm -rf '${_r5}/fifo' && ${_r5_fifo} && rm '${_r5}/fifo/ARL360.at2' && mkfifo '${_r5}/fifo/ARL360.at2' && @EXE@ records show ARL360 --catalogue '${_r5}/fifo/catalogue.json'")
# Class 3, spectra.bin validated after its hash: an ordinate of 1e300 (its
# hash made right) is not used, with the reason, and the selection integrates.
string(REPLACE "DIR" "${_r5}/spectra" _r5_spectra "${_r5_lib}")
rel4_sh_test(rel5_spectra_huge_ordinate 3 "precomputed spectra were not used \\(record spectra '.*spectra.bin': record elCentro: PSA 1e\\+300 m/s\\^2 at T = .*expected a positive value at most PGA/\\(xi sqrt\\(1 - xi\\^2\\)\\).*integrated instead"
  "rm -rf '${_r5}/spectra' && ${_r5_spectra} && python3 '${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/damage_spectra.py' '${_r5}/spectra/spectra.bin' 300 1e300 && @EXE@ records select --ag 0.25 --F0 2.4 --Tc-star 0.3 --near-fault include --mw-min 6 --mw-max 7.5 --r-max 100 --count 1 --catalogue '${_r5}/spectra/catalogue.json' 2>&1; exit 3")
# Class 4, outputs of one run onto one file (exit 0 before, one replacing the other).
rel4_sh_test(rel5_pdf_docx_same 2 "--pdf .*/r.pdf and --docx .*/r.pdf are the same file: one output would replace the other"
  "mkdir -p '${_r5}/same' && @EXE@ run mechanisms/two_storey_facade.json --pdf '${_r5}/same/r.pdf' --docx '${_r5}/same/r.pdf'")
rel4_sh_test(rel5_html_pdf_spelled 2 "--html .*/r.pdf and --pdf .*/./r.pdf are the same file"
  "mkdir -p '${_r5}/same' && @EXE@ run mechanisms/two_storey_facade.json --html '${_r5}/same/r.pdf' --pdf '${_r5}/same/./r.pdf'")
rel4_sh_test(rel5_txt_html_docx_one_name 2 "--html .*/one and --docx .*/one are the same file"
  "mkdir -p '${_r5}/same' && @EXE@ run mechanisms/two_storey_facade.json --html '${_r5}/same/one' --txt '${_r5}/same/two' --docx '${_r5}/same/one'")
rel4_sh_test(rel5_txt_onto_expanded 2 "--txt .*/D/M1.json and --expand .*/D .*/D/M1.json are the same file.*nothing written"
  "rm -rf '${_r5}/expand' && @EXE@ run tests/cli/building/palazzo_sulmona.json --expand '${_r5}/expand/D' --txt '${_r5}/expand/D/M1.json'; rc=$?; test -z \"$(ls '${_r5}/expand/D')\" && echo nothing written >&2; exit $rc")
# Class 5, process limits and signals: a write beyond `ulimit -f` is a full
# disk (SIGXFSZ killed the tool, leaving .NAME.tmp.XXXXXX); SIGTERM and SIGINT
# during --pdf and --docx stop the child and its children and remove every
# temporary (tests/cli/scripts/signal_cleanup.py, with stand-in tools).
rel4_sh_test(rel5_ulimit_html 1 "--html: .*/r.html: cannot write: File too large.*no temporary left"
  "rm -rf '${_r5}/ulimit' && mkdir -p '${_r5}/ulimit' && (ulimit -f 64; @EXE@ run mechanisms/two_storey_facade.json --html '${_r5}/ulimit/r.html' > /dev/null); rc=$?; test -z \"$(ls -A '${_r5}/ulimit')\" && echo no temporary left >&2; exit $rc")
foreach(_sig TERM INT)
  foreach(_mode pdf docx)
    add_test(NAME cli.rel5_sig${_sig}_${_mode}
      COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/signal_cleanup.py $<TARGET_FILE:assess_cli> ${_mode} ${_sig}
              ${_r5}/sig_${_sig}_${_mode}
      WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
    set_tests_properties(cli.rel5_sig${_sig}_${_mode} PROPERTIES LABELS cli TIMEOUT 180
      ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}" PASS_REGULAR_EXPRESSION "^ok: ${_sig} during --${_mode}")
  endforeach()
endforeach()
# Class 6, the record library's inputs under the rules of case files.
assess_cli_error_test(rel5_catalogue_escape "catalogue_escape.json: /records/0/event: the text holds a control character \\(U\\+001B\\)"
  records list --catalogue tests/data/hostile/catalogue_escape.json)
assess_cli_error_test(rel5_catalogue_mw "catalogue_numbers.json: /records/0/Mw: value 1e\\+308 out of range: expected in \\[2, 10\\] -"
  records list --catalogue tests/data/hostile/catalogue_numbers.json)
assess_cli_error_test(rel5_catalogue_distance "catalogue_distance.json: /records/0/distance_km: value -5 out of range: expected in \\[0, 20000\\] km"
  records show RSN292_ITALY_A-STU270 --catalogue tests/data/hostile/catalogue_distance.json)
assess_cli_error_test(rel5_catalogue_dt_zero "catalogue_dt_zero.json: /records/0/dt_s: value 0 out of range: expected in \\[1e-06, 10\\] s"
  records select --ag 0.25 --F0 2.4 --Tc-star 0.3 --catalogue tests/data/hostile/catalogue_dt_zero.json)
assess_cli_error_test(rel5_record_header_escape "header_escape.AT2: the header's event: the text holds a control character \\(U\\+001B\\)"
  rocking --model rigid --thickness 0.25 --height 3 --unit-weight 12 --record tests/data/hostile/header_escape.AT2)
assess_cli_test(rel5_catalogue_ok ARGS records show RSN292_ITALY_A-STU270 --catalogue tests/data/hostile/catalogue_ok.json
  PASS "RSN292_ITALY_A-STU270 .*5 % spectrum")
assess_cli_error_test(rel5_metadata_hex "metadata_hex_mw.csv:2 column Mw: must be a decimal number, got '0x1.bcp2' \\(a hexadecimal number\\)"
  records build --metadata tests/data/hostile/metadata_hex_mw.csv --output ${_r5}/meta/catalogue.json)
assess_cli_error_test(rel5_metadata_escape "metadata_escape.csv:2 column event: the text holds a control character \\(U\\+001B\\)"
  records build --metadata tests/data/hostile/metadata_escape.csv --output ${_r5}/meta/catalogue.json)
assess_cli_error_test(rel5_metadata_dup_column "metadata_dup_column.csv:1: column 'Mw' is named twice \\(columns 4 and 24\\)"
  records build --metadata tests/data/hostile/metadata_dup_column.csv --output ${_r5}/meta/catalogue.json)
assess_cli_error_test(rel5_metadata_empty_id "metadata_empty_id.csv:2 column file: '../../../spectra/records/.AT2' gives an empty record id"
  records build --metadata tests/data/hostile/metadata_empty_id.csv --output ${_r5}/meta/catalogue.json)
rel4_sh_test(rel5_build_output_elsewhere 3 "wrote .*elsewhere/deeper/catalogue.json: 4 components.*ARL360 \\(\\.\\./.*spectra/records/ARL360.at2, PEER AT2\\).*5 % spectrum"
  "rm -rf '${_r5}/elsewhere' && mkdir -p '${_r5}/elsewhere/deeper' && @EXE@ records build --metadata tests/data/records_mini/metadata.csv --output '${_r5}/elsewhere/deeper/catalogue.json' && @EXE@ records show ARL360 --catalogue '${_r5}/elsewhere/deeper/catalogue.json'; exit 3")
# Class 7, every option with its range and reason: generated over every
# number option of every subcommand (tests/cli/scripts/option_ranges.py);
# and the inputs of the issue.
add_test(NAME cli.rel5_option_ranges
  COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/option_ranges.py $<TARGET_FILE:assess_cli>
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.rel5_option_ranges PROPERTIES LABELS cli TIMEOUT 300
  ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}" PASS_REGULAR_EXPRESSION "^ok: [0-9]+ number options of [0-9]+ subcommands")
assess_cli_error_test(rel5_fragility_records_zero "--records: value 0 out of range: expected in \\[1, 1000\\] records"
  fragility tests/data/fragility/free_wall.json --records 0)
assess_cli_error_test(rel5_near_fault_km_negative "--near-fault-km: value -1 out of range: expected in \\[0, 100\\] km"
  records select --lat 43.44 --lon 12.64 --near-fault-km -1)
assess_cli_error_test(rel5_max_pga_ratio_zero "--max-pga-ratio: value 0 out of range: expected in \\[0\\.5, 10\\] -"
  records select --lat 43.44 --lon 12.64 --max-pga-ratio 0)
assess_cli_error_test(rel5_F0_huge "--F0: value 1e\\+300 out of range: expected in \\[1, 10\\] -"
  records select --ag 0.25 --F0 1e300 --Tc-star 0.3)
assess_cli_error_test(rel5_flexure_fm_tiny "flexure_fm_tiny.json: /mechanism/fm_MPa: value 1e-09 out of range: expected in \\[0\\.001, 10000\\] MPa"
  kinematic tests/data/hostile/flexure_fm_tiny.json)
assess_cli_error_test(rel5_corner_opening_beyond "corner_opening_beyond.json: /mechanism/wall_a/openings/0/to: the opening ends 9 m from the corner's outer face, beyond the wall's end \\(6\\.5 m"
  kinematic tests/data/hostile/corner_opening_beyond.json)
# Class 8, messages that name the user's file and the real cause.
rel4_sh_test(rel5_tmpdir_missing 2 "cannot create a temporary folder in TMPDIR=/nonexistent/assess: No such file or directory \\(set TMPDIR to a writable folder\\)"
  "mkdir -p '${_r5}/tmpdir' && TMPDIR=/nonexistent/assess @EXE@ run mechanisms/two_storey_facade.json --pdf '${_r5}/tmpdir/r.pdf' > /dev/null")
# The Word document needs no program (issue 36, item 7; it needed pandoc): written with nothing on PATH.
rel4_sh_test(rel5_docx_without_programs 3 "Word .*/noprograms/r.docx: a zip archive"
  "rm -rf '${_r5}/noprograms' && mkdir -p '${_r5}/noprograms' && PATH=/nonexistent @EXE@ run mechanisms/two_storey_facade.json --docx '${_r5}/noprograms/r.docx' > /dev/null && head -c 2 '${_r5}/noprograms/r.docx' | grep -q PK && echo 'Word ${_r5}/noprograms/r.docx: a zip archive' >&2; exit 3")
# `assess dynamic --k`: a k the command line gave is named as --k, not as the
# case's /dynamic/k (which this case does not have).
assess_cli_error_test(rel5_dynamic_k_option "assess: error: --k: Winkler modulus k = 100000 kN/m\\^3 is too small"
  dynamic mechanisms/vertical_flexure_dynamic.json --model smooth --k 1e5 --record spectra/records/RSN292_ITALY_A-STU270.AT2)
# No `timeout` (nor pdftohtml, qpdf) on PATH: the PDF is printed all the same
# (the programs run without a shell and time out in the tool).
rel4_sh_test(rel5_pdf_without_timeout 3 "PDF report written to:? .*/notimeout/r.pdf"
  "rm -rf '${_r5}/notimeout' && mkdir -p '${_r5}/notimeout' && PATH=/nonexistent CHROMIUM='${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/fake_chromium.sh' @EXE@ run mechanisms/two_storey_facade.json --lang en --pdf '${_r5}/notimeout/r.pdf' && head -c 4 '${_r5}/notimeout/r.pdf' | grep -q PDF; exit 3")
# The PDF writer's DevTools client (issue 36, item 7: one browser for every
# print of a run) against a stand-in that speaks the protocol on descriptors
# 3 and 4: the PDF it sends in base 64 is the file written; a protocol error,
# a browser that ends mid-print and an answer of the wrong form are errors
# naming the browser (exit 2).
rel4_sh_test(rel6_pdf_devtools 3 "printed by fake_devtools.py through the DevTools pipe"
  "rm -rf '${_r5}/devtools' && mkdir -p '${_r5}/devtools' && PATH=/nonexistent CHROMIUM='${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/fake_devtools.py' @EXE@ run mechanisms/two_storey_facade.json --lang en --pdf '${_r5}/devtools/r.pdf' > /dev/null && cat '${_r5}/devtools/r-tabulati.pdf'; exit 3")
# (each test its own folder: they run side by side)
rel4_sh_test(rel6_pdf_devtools_refused 2 "--pdf: .*fake_devtools.py refused Page.printToPDF: Printing failed"
  "mkdir -p '${_r5}/devtools_refused' && FAKE_DEVTOOLS=refuse PATH=/nonexistent CHROMIUM='${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/fake_devtools.py' @EXE@ run mechanisms/two_storey_facade.json --lang en --pdf '${_r5}/devtools_refused/r.pdf' > /dev/null")
rel4_sh_test(rel6_pdf_devtools_died 2 "--pdf: .*fake_devtools.py ended before it finished printing"
  "mkdir -p '${_r5}/devtools_died' && FAKE_DEVTOOLS=die PATH=/nonexistent CHROMIUM='${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/fake_devtools.py' @EXE@ run mechanisms/two_storey_facade.json --lang en --pdf '${_r5}/devtools_died/r.pdf' > /dev/null")
rel4_sh_test(rel6_pdf_devtools_malformed 2 "--pdf: .*fake_devtools.py sent an answer of an unexpected form"
  "mkdir -p '${_r5}/devtools_malformed' && FAKE_DEVTOOLS=malformed PATH=/nonexistent CHROMIUM='${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/fake_devtools.py' @EXE@ run mechanisms/two_storey_facade.json --lang en --pdf '${_r5}/devtools_malformed/r.pdf' > /dev/null")
# Class 9, bounded work: one horizontal-flexure mechanism at its caps (20
# strips of 6 openings, 200 search points: 0.2-0.3 s of CPU; at the former
# caps, 50 strips of 20 openings, 57 s; docs/reliability.md states the time).
add_test(NAME cli.rel5_flexure_caps COMMAND $<TARGET_FILE:assess_cli> kinematic tests/data/hostile/flexure_caps.json
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.rel5_flexure_caps PROPERTIES LABELS cli TIMEOUT 30
  ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}" PASS_REGULAR_EXPRESSION "horizontal_flexure")
