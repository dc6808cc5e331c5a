# CLI tests of `assess rocking` (public interface: options and JSON keys).
set(_rk_stu spectra/records/RSN292_ITALY_A-STU270.AT2)
set(_rk_block --thickness 0.25 --height 3 --unit-weight 12.06)

# --json prints one object with every documented key (nlohmann sorts the keys).
assess_cli_test(rocking_json_keys
  ARGS rocking --model smooth ${_rk_block} --k 1e6 --record ${_rk_stu} --scale 0.2 --json
  PASS "\"alpha\": 0\\.0831[0-9]*,.*\"capacity\": .*\"dc\": .*\"impacts\": [0-9]+,.*\"overturned\": false,.*\"restitution\": 0\\.98965[0-9]*,.*\"t_overturn\": null,.*\"t_theta_max\": .*\"termination\": \"completed\",.*\"theta_cr\": 0\\.00028944[0-9]*,.*\"theta_max\": .*\"theta_u\": 0\\.0798")
# rigid block: theta_cr is null, theta_u = alpha
assess_cli_test(rocking_rigid_json
  ARGS rocking --model rigid ${_rk_block} --record ${_rk_stu} --scale 0.2 --json
  PASS "\"theta_cr\": null,.*\"theta_u\": 0\\.0831412")
# a slender rigid block under the Rinaldi near-fault record overturns
assess_cli_test(rocking_overturns
  ARGS rocking --model rigid --thickness 0.25 --height 3 --unit-weight 18 --record spectra/records/Rinaldi228.AT2 --json
  PASS "\"overturned\": true,.*\"t_overturn\": [0-9.]+,.*\"termination\": \"overturned\"")
assess_cli_test(rocking_overturn_half_pi
  ARGS rocking --model rigid --thickness 0.25 --height 3 --unit-weight 18 --record spectra/records/Rinaldi228.AT2
       --overturn-at half_pi --json
  PASS "\"overturned\": true,.*\"theta_max\": 1\\.5707963")
# one-sided smooth facade, seed-convention restitution, reversed polarity; human-readable output
assess_cli_test(rocking_one_sided_human
  ARGS rocking --model smooth --thickness 0.5 --height 4 --unit-weight 18 --k 5e5 --one-sided --restitution -0.65
       --record ${_rk_stu} --reverse
  PASS "one-sided.*reversed.*restitution    = -0\\.650000.*termination    = completed")
assess_cli_test(rocking_one_sided_theory
  ARGS rocking --model rigid --thickness 0.5 --height 4 --unit-weight 18 --one-sided --restitution one-sided-theory
       --record ${_rk_stu} --json
  PASS "\"restitution\": -0\\.4")
# plain record with declared time step and unit; history CSV with a header with units
assess_cli_test(rocking_plain_history
  ARGS rocking --model smooth ${_rk_block} --k 1e6 --record tests/data/rocking_plain_2col.txt --dt 0.01 --unit g
       --history ${CMAKE_CURRENT_BINARY_DIR}/rocking_history.csv --json
  PASS "\"format\": \"plain\"")
add_test(NAME cli.rocking_history_header
  COMMAND ${CMAKE_COMMAND} -E cat ${CMAKE_CURRENT_BINARY_DIR}/rocking_history.csv)
set_tests_properties(cli.rocking_history_header PROPERTIES LABELS cli DEPENDS cli.rocking_plain_history
  PASS_REGULAR_EXPRESSION "^t_s,theta_rad,omega_rad_s\n0,0,0\n")

# Bad input: a clear message and a non-zero exit
assess_cli_error_test(rocking_err_truncated "truncated record: the header declares 12 points, the file has 8"
  rocking --model rigid ${_rk_block} --record tests/data/rocking_truncated.AT2)
assess_cli_error_test(rocking_err_nonnumeric "rocking_nonnumeric.AT2:5: non-numeric value 'abc'"
  rocking --model rigid ${_rk_block} --record tests/data/rocking_nonnumeric.AT2)
assess_cli_error_test(rocking_err_zero_dt "--dt: value 0 out of range: expected in \\[1e-06, 10\\] s"
  rocking --model rigid ${_rk_block} --record tests/data/rocking_plain_1col.txt --dt 0 --unit cm/s^2)
assess_cli_error_test(rocking_err_negative_dt "--dt: value -0\\.01 out of range: expected in \\[1e-06, 10\\] s"
  rocking --model rigid ${_rk_block} --record tests/data/rocking_plain_1col.txt --dt -0.01)
assess_cli_error_test(rocking_err_k_small "is too small: the block has no restoring branch unless k > 3 W h / \\(2 b\\^3\\)"
  rocking --model smooth ${_rk_block} --k 1e3 --record ${_rk_stu})
assess_cli_error_test(rocking_err_restitution "restitution must be in \\[-1, 1\\]"
  rocking --model rigid ${_rk_block} --restitution 2 --record ${_rk_stu})
assess_cli_error_test(rocking_err_restitution_text "--restitution expects a number"
  rocking --model rigid ${_rk_block} --restitution bouncy --record ${_rk_stu})
assess_cli_error_test(rocking_err_housner_one_sided "'housner' applies to two-sided rocking"
  rocking --model rigid ${_rk_block} --one-sided --restitution housner --record ${_rk_stu})
assess_cli_error_test(rocking_err_k_rigid "--k applies only to --model smooth"
  rocking --model rigid ${_rk_block} --k 1e6 --record ${_rk_stu})
assess_cli_error_test(rocking_err_model "--model must be 'smooth' or 'rigid'"
  rocking --model soft ${_rk_block} --record ${_rk_stu})
assess_cli_error_test(rocking_err_no_k "--k \\(Winkler modulus, kN/m\\^3\\) is required"
  rocking --model smooth ${_rk_block} --record ${_rk_stu})
assess_cli_error_test(rocking_err_unit_without_dt "--unit applies only to a plain record file"
  rocking --model rigid ${_rk_block} --record ${_rk_stu} --unit cm/s^2)

# `assess dynamic CASE --record FILE`: a case file's mechanism (issue 13).
assess_cli_test(dynamic_flexure_json
  ARGS dynamic mechanisms/vertical_flexure_dynamic.json --record spectra/records/RSN292_ITALY_A-STU270.AT2 --reverse --restitution -0.5 --json
  PASS "\"d_control\": 0\\.0917.*\"d_star\": 0\\.110.*\"impacts\": 64,.*\"overturned\": false.*\"termination\": \"completed\".*\"theta_u\": 0\\.04169")
assess_cli_test(dynamic_history
  ARGS dynamic mechanisms/upper_storey_dynamic.json --record spectra/records/RSN285_ITALY_A-BAG000.AT2 --history ${CMAKE_CURRENT_BINARY_DIR}/dynamic_history.csv
  PASS "base at Z = 4.00 m.*theta_max .*d_control")
assess_cli_error_test(dynamic_chain_housner "a chain of several blocks needs a given coefficient.*housner"
  dynamic mechanisms/vertical_flexure_dynamic.json --record spectra/records/RSN292_ITALY_A-STU270.AT2 --restitution housner)
assess_cli_error_test(dynamic_smooth_no_k "--k \\(Winkler modulus, kN/m\\^3\\) is required"
  dynamic mechanisms/vertical_flexure_dynamic.json --record spectra/records/RSN292_ITALY_A-STU270.AT2 --model smooth)
