# CLI tests of `assess kinematic`: the report, the JSON keys, the §6b wall
# numbers at L'Aquila, and each bad input with a named element and exit != 0.
assess_cli_test(kinematic_report ARGS kinematic mechanisms/free_wall_laquila.json
  PASS "a0\\* = alpha0 g/\\(e\\* FC\\).*0\\.807407 m/s2")
assess_cli_test(kinematic_report_verdict ARGS kinematic mechanisms/free_wall_laquila.json
  PASS "non verificato / not satisfied")
assess_cli_test(kinematic_json_keys ARGS kinematic mechanisms/free_wall_laquila.json --json
  PASS "\"M_star\": 4\\.1284.*\"T_SLC\": 3\\.8566.*\"T_SLV\": 2\\.7688.*\"Ts\": 1\\.7619")
assess_cli_test(kinematic_json_checks ARGS kinematic mechanisms/free_wall_laquila.json --json
  PASS "\"index\": {[^}]*\"ag_capacity_g\": 0\\.20364[^}]*\"zeta_E\": 0\\.78128")
assess_cli_test(kinematic_json_curve ARGS kinematic mechanisms/free_wall_laquila.json --json
  PASS "\"capacity_curve\": \\[[^]]*\"a_star\"[^]]*\"d_star\"")
assess_cli_test(kinematic_facade ARGS kinematic mechanisms/two_storey_facade.json PASS "<- governing")
assess_cli_test(kinematic_flexure ARGS kinematic mechanisms/vertical_flexure.json PASS "minimum of alpha0")
assess_cli_test(kinematic_gable ARGS kinematic mechanisms/gable.json PASS "C8A.4.12")
assess_cli_test(kinematic_composite ARGS kinematic mechanisms/composite_wedge.json PASS "wedge beta = 45.0 deg")
assess_cli_test(kinematic_blocks ARGS kinematic mechanisms/explicit_blocks.json PASS "no site in the case")
assess_cli_error_test(kinematic_two_dof "/mechanism: the chain has 4 degrees of freedom.*block 1 'b'" kinematic tests/cli/kinematic_bad/two_dof.json)
assess_cli_error_test(kinematic_zero_dof "0 degrees of freedom" kinematic tests/cli/kinematic_bad/zero_dof.json)
assess_cli_error_test(kinematic_hinge_off_block "/mechanism/constraints/0/point: the point is not on block \"a\"" kinematic tests/cli/kinematic_bad/hinge_off_block.json)
assess_cli_error_test(kinematic_load_outside "/mechanism/loads/0/point: the load lies outside every block" kinematic tests/cli/kinematic_bad/load_outside.json)
assess_cli_error_test(kinematic_negative_thickness "/mechanism/storeys/0/thickness: value -0.4 out of range: expected in \\[0.001, 1000\\] m" kinematic tests/cli/kinematic_bad/negative_thickness.json)
assess_cli_error_test(kinematic_not_activated "statically unstable.*alpha0 = -" kinematic tests/cli/kinematic_bad/not_activated.json)
assess_cli_error_test(kinematic_unknown_key "unknown key \"thicknes\" \\(did you mean \"thickness\"\\?\\)" kinematic tests/cli/kinematic_bad/unknown_key.json)
assess_cli_error_test(kinematic_missing_file "kinematic|exist" kinematic tests/cli/kinematic_bad/none.json)
# Issues 33, 38: the corner about the two axes along the walls (an axis between them is never lower;
# the former 45 deg reduction, alpha0 0.348193, reported beside them), its displacement bounded by the pier.
assess_cli_test(kinematic_corner ARGS kinematic mechanisms/corner.json
  PASS "corner_overturning, governing candidate: axis at (0|90)\\.0 deg from wall A.*α0 about the axis at 45° \\(the classical reduction, for comparison\\) = 0\\.348193.*d0\\* bound +0\\.2[0-9]+ m.*the corner pier's own overturning")
assess_cli_error_test(kinematic_corner_axis_scan "/mechanism/axis_points: the axis is not scanned: the two axes along the walls"
  kinematic tests/schema/bad/corner_axis_scan.json)
# Issue 38: the composite wedge bounded by the façade's own overturning (docs/theory/mechanisms.md §5).
assess_cli_test(kinematic_composite_bound ARGS kinematic mechanisms/composite_wedge.json
  PASS "d0\\* bound +0\\.[0-9]+ m .*the façade's own overturning about its")
assess_cli_test(kinematic_corner_unequal ARGS kinematic mechanisms/corner_unequal.json
  PASS "governing candidate: axis at 0\\.0 deg from wall A.*axis at 0\\.0 deg from wall A +0\\.065777")
# Issue 33: horizontal flexure (notes §1.6: 0.346074), the side walls' friction (0.467333, the wedge
# 0.387427, the bare façade 0.0833333), the roof thrust (0.018263; 0.141379 without the thrust).
assess_cli_test(kinematic_horizontal_flexure ARGS kinematic mechanisms/horizontal_flexure.json
  PASS "arch thrust H = H_lim \\(the restraint governs\\) = 20 kN.*strip z = 6\\.50-7\\.50 m, middle hinge at u = 2\\.50 m\n +0\\.346074")
assess_cli_test(kinematic_friction ARGS kinematic mechanisms/friction_overturning.json
  PASS "bare façade \\(no interlocking, no seat friction\\) = 0\\.0833333.*with the side walls' friction = 0\\.467333.*wedges \\(composite\\) = 0\\.387427")
assess_cli_test(kinematic_roof_thrust ARGS kinematic mechanisms/roof_thrust.json
  PASS "roof: thrust H per metre = 3\\.21333 kN/m.*α0 without the roof thrust = 0\\.141379.*alpha0 +\\[C8A\\.4\\.1 / C8\\.7\\.1\\.1\\] +0\\.018263")
assess_cli_test(kinematic_issue33_json ARGS kinematic mechanisms/horizontal_flexure.json --json
  PASS "\"d0_star_bound\": null.*\"data\": \\[.*\"label\": \"span between the transverse walls L\".*\"quantities\": \\[")
assess_cli_error_test(kinematic_flexure_no_restraint "/mechanism/supports: expected \"rigid\": true or at least one of"
  kinematic tests/cli/kinematic_bad/flexure_no_restraint.json)
assess_cli_error_test(kinematic_roof_strut_unstable "statically unstable.*\"roof thrust\" \\(force"
  kinematic tests/cli/kinematic_bad/roof_strut_unstable.json)
assess_cli_error_test(kinematic_corner_opening_in_pier "/mechanism/wall_a/openings/0/from: the opening starts 0\\.2.* inside the corner pier"
  kinematic tests/cli/kinematic_bad/corner_opening_in_pier.json)
