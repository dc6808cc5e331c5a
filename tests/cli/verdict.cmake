# CLI tests of issue 11 (verdicts an engineer can sign): the summary by
# approach, the governing mechanism, dynamic verdicts, plain records, the
# statically unstable wall, plausibility warnings and the JSON version keys.
# Each of these failed on the tree before the issue (noted per test).

# Gable: the summary carries the failing at-height rows (before: only the two
# NTC 2008 ground rows, "<= 1").
assess_cli_test(verdict_gable_summary ARGS run mechanisms/gable.json --lang en
  PASS "Conclusion \\(adopted procedure: non-linear kinematic analysis \\(displacement\\), NTC 2018\\): NOT SATISFIED, D/C = 1\\.129.*NTC 2008 — for comparison.*linear kinematic analysis \\(strength\\): NOT SATISFIED, D/C = 2\\.226.*at height.*NTC 2018.*linear kinematic analysis \\(strength\\): NOT SATISFIED, D/C = 2\\.237.*at height, D/C = 2\\.237")
assess_cli_test(verdict_gable_json ARGS run mechanisms/gable.json --json
  PASS "\"comparison\": \\[[^{}]*\\{[^{}]*\"approach\": \"strength\",[^{}]*\"dc\": 2\\.22[^{}]*\"limit_state\": \"SLV\",[^{}]*\"location\": \"height\",[^{}]*\"satisfied\": false")
# Two-storey façade: the first-floor hinge governs (before: the ground hinge, smallest alpha0).
assess_cli_test(verdict_two_storey_governing ARGS kinematic mechanisms/two_storey_facade.json
  PASS "governing = largest D/C over its checks")
# An overturning under one of two records: "overturned in 1 of 2" and a collapse,
# never "<= 1" (before: "dynamic energy D/C 0.513 <= 1").
assess_cli_test(verdict_overturn_two_records ARGS run tests/cli/verdict/overturn_two_records.json --lang en
  PASS "non-linear dynamic analysis: NOT SATISFIED, D/C = ∞.*d0 exceeded in 1 of 2 analyses \\(overturned in 1\\).*e = -0\\.650 +2 +1 / 2 +∞"
  FAIL_REGEX "no overturning")
# Plain records (one column with dt and unit, two columns with the unit only)
# through the same reader as `assess rocking` (before: unknown key "dt").
assess_cli_test(verdict_plain_records ARGS run tests/cli/verdict/plain_records.json --lang en
  PASS "largest peak d\\* of 3 records.*elcentro_plain_1col .*elcentro_plain_2col_cms2 ")
# 80 kN thrust: statically unstable, exit 2, alpha0 and the thrust named
# (before: "never activated: alpha0 = -1.43 <= 0").
assess_cli_error_test(verdict_thrust_unstable
  "thrust_80kN.json: /mechanism: the wall is statically unstable: it overturns under its static loads alone.*alpha0 = -1\\.427.*thrust level 1.*80 kN"
  kinematic tests/cli/verdict/thrust_80kN.json)
assess_cli_error_test(verdict_thrust_unstable_run "statically unstable" run tests/cli/verdict/thrust_80kN.json)
# Thickness in cm, unit weight in kg/m^3: warnings on stderr, the run goes on
# (before: alpha0 = 12 and every check "verificato", silently).
assess_cli_test(verdict_cm_thickness ARGS kinematic tests/cli/verdict/cm_thickness.json
  PASS "warning: tests/cli/verdict/cm_thickness.json: /mechanism/storeys/0/thickness = 60 m is outside the plausible range 0\\.05-3 m.*typed in cm")
assess_cli_test(verdict_cm_thickness_json ARGS run tests/cli/verdict/cm_thickness.json --json
  PASS "\"warnings\": \\[[^[]*/mechanism/unit_weight = 1800 kN/m\\^3")
# Every --json carries assess_version and schema_version.
assess_cli_test(verdict_version_kinematic ARGS kinematic mechanisms/gable.json --json
  PASS "\"assess_version\": \"[0-9.]+\".*\"schema_version\": 1")
assess_cli_test(verdict_version_run ARGS run mechanisms/gable.json --json
  PASS "\"assess_version\": \"[0-9.]+\".*\"schema_version\": 1")
assess_cli_test(verdict_version_spectrum ARGS spectrum --lat 42.35 --lon 13.40 --limit-state SLV --json
  PASS "\"assess_version\": \"[0-9.]+\".*\"schema_version\": 1")
assess_cli_test(verdict_version_rocking
  ARGS rocking --model rigid --thickness 0.4 --height 4 --unit-weight 18 --record spectra/records/elCentro.AT2 --json
  PASS "\"assess_version\": \"[0-9.]+\".*\"schema_version\": 1")
# `assess rocking` reads a two-column plain file with --unit alone (dt from the
# time column), as the case files' {"file", "unit"} do.
assess_cli_test(verdict_rocking_two_columns_unit_only
  ARGS rocking --model smooth --k 1e6 --thickness 0.4 --height 4 --unit-weight 18 --one-sided --restitution -0.65
       --record tests/data/elcentro_plain_2col_cms2.txt --unit cm/s^2 --json
  PASS "\"dt\": 0\\.02.*\"format\": \"plain\"|\"format\": \"plain\".*\"dt\": 0\\.02")
# Plain records in a case file: the same analyses as `assess rocking` on the same files.
add_test(NAME cli.verdict_plain_case_vs_rocking
  COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:assess_cli> -DSRC=${PROJECT_SOURCE_DIR}
          -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/plain_case_vs_rocking.cmake)
set_tests_properties(cli.verdict_plain_case_vs_rocking PROPERTIES LABELS cli
  ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}")
# Issue 21: `assess run` and `assess rocking` on the same wall and motion agree
# to 1e-10 (theta_max, energy D/C, centroid displacement; impacts, overturning
# and the end reason equal): rigid/smooth x one-/two-sided x both polarities x
# a one-sine pulse and El Centro, the catalogue's wall and the same wall as an
# explicit one-block chain.
add_test(NAME cli.run_vs_rocking
  COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/run_vs_rocking.py $<TARGET_FILE:assess_cli> ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.run_vs_rocking PROPERTIES LABELS cli ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}")
