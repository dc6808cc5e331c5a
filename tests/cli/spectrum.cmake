# CLI tests of `assess spectrum` (issue 2).
assess_cli_test(spectrum_table ARGS spectrum --lat 42.3498 --lon 13.3995 --soil B
  PASS "SLO.*SLD.*SLV.*SLC")
assess_cli_test(spectrum_json_keys ARGS spectrum --lat 42.3498 --lon 13.3995 --limit-state SLV --json --periods 0,0.5,1
  PASS "\"CC\".*\"F0\".*\"S\".*\"SS\".*\"ST\".*\"TB\".*\"TC\".*\"TD\".*\"TR\".*\"Tc_star\".*\"ag_g\".*\"eta\".*\"spectrum\".*\"SDe_m\".*\"Se_g\".*\"T\"")
assess_cli_test(spectrum_json_laquila_ag ARGS spectrum --lat 42.3498 --lon 13.3995 --tr 475 --json
  PASS "\"ag_g\": 0\\.2607")
assess_cli_test(spectrum_given ARGS spectrum --ag 0.25 --F0 2.4 --Tc-star 0.3 --soil C --limit-state SLV --json --periods 0
  PASS "\"Se_g\": 0\\.33[0-9]+")
assess_cli_test(spectrum_island ARGS spectrum --island Sardegna --limit-state SLV --json --periods 0
  PASS "\"ag_g\": 0\\.0499")
assess_cli_test(spectrum_use_class ARGS spectrum --lat 41.8933 --lon 12.4829 --use-class IV --limit-state SLC --json --periods 1
  PASS "\"TR\": 1949\\.5")
assess_cli_test(spectrum_clamp_warning ARGS spectrum --lat 42.3498 --lon 13.3995 --use-class I --limit-state SLO
  PASS "clamped|outside the tabulated")
assess_cli_error_test(spectrum_bad_lat "--lat: value 95 out of range: expected in \\[-90, 90\\] deg" spectrum --lat 95 --lon 13)
assess_cli_error_test(spectrum_outside_grid "outside the NTC hazard grid" spectrum --lat 48.85 --lon 2.35)
assess_cli_error_test(spectrum_bad_soil "--soil.*A, B, C, D, E" spectrum --lat 42.35 --lon 13.40 --soil Z)
assess_cli_error_test(spectrum_bad_damping "--damping: value -3 out of range: expected in \\[0, 100\\] %" spectrum --lat 42.35 --lon 13.40 --damping -3)
assess_cli_error_test(spectrum_bad_tr "--tr.*years" spectrum --lat 42.35 --lon 13.40 --tr 0)
assess_cli_error_test(spectrum_bad_grid "/nonexistent/grid.csv: cannot open the hazard grid file" spectrum --lat 42.35 --lon 13.40 --grid /nonexistent/grid.csv)
assess_cli_error_test(spectrum_bad_periods "--periods" spectrum --lat 42.35 --lon 13.40 --periods 0,abc)
assess_cli_error_test(spectrum_bad_limit_state "--limit-state.*SLO, SLD, SLV, SLC" spectrum --lat 42.35 --lon 13.40 --limit-state ULS)
assess_cli_error_test(spectrum_no_site "exactly one" spectrum --soil B)
assess_cli_error_test(spectrum_bad_island "not in Allegato B" spectrum --island Atlantide)
assess_cli_error_test(spectrum_bad_topography "--topography.*T1, T2, T3, T4" spectrum --lat 42.35 --lon 13.40 --topography T7)
