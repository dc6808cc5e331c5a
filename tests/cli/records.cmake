# CLI tests of `assess records` (issue 12): build, list/filter, show, select, errors.
# The build on a small library (tests/data/records_mini: 3 short records and an
# excluded plain file), catalogue and precomputed spectra; the shipped
# catalogue's reproduction is unit.record_library (its spectra: numeric.record_spectra).
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/records_mini)
assess_cli_test(records_build ARGS records build --metadata tests/data/records_mini/metadata.csv
  --output ${CMAKE_CURRENT_BINARY_DIR}/records_mini/catalogue.json
  PASS "4 components, 3 usable for design.*spectra.bin: 5 % PSA of 3 components at 602 periods")
assess_cli_test(records_list_mw ARGS records list --mw-min 6.25 --mw-max 6.35
  PASS "16837_H2.*L.Aquila 2009.*yes +yes.*RSN266_1 +Victoria Mexico.*18 of 450 components"
  FAIL_REGEX "Irpinia|Friuli")
assess_cli_test(records_list_all ARGS records list --all PASS "450 of 450 components")
assess_cli_test(records_show_json ARGS records show RSN292_ITALY_A-STU270 --json
  PASS "\"positive_direction\": \"W\".*\"site_class\": \"B\".*\"pga_g\": 0\\.320522.*\"psa_g\"")
# Issue 30: enough class-C records, no relaxation; near-fault records left out.
assess_cli_test(records_select_church_site ARGS records select --lat 43.44 --lon 12.64 --soil C --t-min 1.37 --t-max 4.0
  PASS "warning: default Mw window.*88 candidates after the filters \\(62 near-fault or pulse-like left out\\).*compatible: mean/target in.*mean scale"
  FAIL_REGEX "site class relaxed|FLAG")
assess_cli_test(records_select_json ARGS records select --ag 0.25 --F0 2.4 --Tc-star 0.3 --soil B --mw-min 6.0 --mw-max 7.0 --r-max 40 --json
  PASS "\"status\": \"compatible\".*\"records\".*\"scale\".*\"deviation\".*\"mean_psa_m_s2\""
  FAIL_REGEX "default Mw window")
assess_cli_error_test(records_show_unknown "record 'nope' is not in the catalogue" records show nope)
assess_cli_error_test(records_bad_site_class "--site-class 'Q': expected A, B, C, D or E" records list --site-class Q)
assess_cli_error_test(records_select_no_site "give the site as --lat/--lon or as --ag" records select)
assess_cli_error_test(records_build_missing "nope.csv: cannot open the record metadata table" records build --metadata nope.csv)
assess_cli_error_test(run_select_bad_class "/dynamic/select/site_classes/0.*expected a site class" run tests/cli/run_bad/select_bad_class.json)
assess_cli_error_test(run_select_bad_mw "/dynamic/select/Mw.*min <= max" run tests/cli/run_bad/select_bad_mw.json)
# Issue 30: 7 class-C records, each scale <= 3.00, the range justified, no nan where metadata lack.
assess_cli_test(run_church_why_chosen ARGS run mechanisms/church-facade.json --lang en
  PASS "C \\(Vs30 192\\).*Period range: 0\\.500 x min.*cut at[ \n]+4\\.000 s.*T_SLC = 6\\.012 s.*Site classes tried: class C: 88 candidates, compatible.*Limits: each scale ≤ 3\\.00, mean scale 1\\.509 ≤ 2\\.00, largest scaled PGA 0\\.446 g ≤ 2\\.50 ag S.*integrated to its last sample"
  FAIL_REGEX "site class relaxed|[ (]-?nan[ ,)]|[ (]-?inf[ ,)]")
# Issue 30: the flags, computed, beside each record: near-fault and pulse-like records admitted on
# request, a misfit above the case's limit; a listed file outside the library has no metadata ("—").
assess_cli_test(run_record_flags ARGS run tests/cli/records/church_flags.json --lang en
  PASS "near-fault: Rjb 6\\.09 km < 10 km; misfit 0\\.254 > 0\\.200 \\(rank 28\\).*pulse-like \\(source classification, Tp = 4\\.51 s\\); near-fault: Rjb 8\\.6 km < 10 km.*near-fault and pulse-like records admitted \\(0 left[ \n]+out"
  FAIL_REGEX "[ (]-?nan[ ,)]|[ (]-?inf[ ,)]")
assess_cli_test(run_listed_record_flags ARGS run tests/cli/verdict/plain_records.json --lang en
  PASS "elcentro_plain_1col +— +— +— +— +— +1\\.000 +0\\.3187 +— +— +31\\.2.*not in the record library: Mw, distance, site class and near-fault status unknown.*elCentro .*6\\.1 Rjb +C \\(Vs30.*near-fault: Rjb 6\\.09 km < 10 km"
  FAIL_REGEX "[ (]-?nan[ ,)]|[ (]-?inf[ ,)]")
