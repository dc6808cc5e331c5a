# CLI tests of `assess records` (issue 12): build, list/filter, show, select, errors.
assess_cli_test(records_build ARGS records build --output ${CMAKE_CURRENT_BINARY_DIR}/records_catalogue_test.json
  PASS "153 components, 84 usable for design")
assess_cli_test(records_list_mw ARGS records list --mw-min 6.25 --mw-max 6.35
  PASS "16837_H2.*L.Aquila 2009.*12 of 153 components"
  FAIL_REGEX "Irpinia|Friuli")
assess_cli_test(records_list_all ARGS records list --all PASS "153 of 153 components")
assess_cli_test(records_show_json ARGS records show RSN292_ITALY_A-STU270 --json
  PASS "\"positive_direction\": \"W\".*\"site_class\": \"B\".*\"pga_g\": 0\\.320522.*\"psa_g\"")
assess_cli_test(records_select_church_site ARGS records select --lat 43.44 --lon 12.64 --soil C --t-min 1.37 --t-max 4.0
  PASS "warning: default Mw window.*warning: site class relaxed from C.*compatible: mean/target in.*mean scale")
assess_cli_test(records_select_json ARGS records select --ag 0.25 --F0 2.4 --Tc-star 0.3 --soil B --mw-min 6.0 --mw-max 7.0 --r-max 40 --json
  PASS "\"status\": \"compatible\".*\"records\".*\"scale\".*\"deviation\".*\"mean_psa_m_s2\""
  FAIL_REGEX "default Mw window")
assess_cli_error_test(records_show_unknown "record 'nope' is not in the catalogue" records show nope)
assess_cli_error_test(records_bad_site_class "--site-class 'Q': expected A, B, C, D or E" records list --site-class Q)
assess_cli_error_test(records_select_no_site "give the site as --lat/--lon or as --ag" records select)
assess_cli_error_test(records_build_missing "nope.csv: cannot open the record metadata table" records build --metadata nope.csv)
assess_cli_error_test(run_select_bad_class "/dynamic/select/site_classes/0.*expected a site class" run tests/cli/run_bad/select_bad_class.json)
assess_cli_error_test(run_select_bad_mw "/dynamic/select/Mw.*min <= max" run tests/cli/run_bad/select_bad_mw.json)
assess_cli_test(run_church_why_chosen ARGS run mechanisms/church-facade.json
  PASS "mean scale 1\\.70[0-9] <= 2\\.00, largest scaled PGA 0\\.55[0-9] g <= 2\\.50 ag S.*warning: site class relaxed from C.*dev rank Mw.*integrated to its last sample")
