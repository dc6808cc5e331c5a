# Site by comune (issue 14): `assess spectrum --comune NAME [--province XX]`
# and "site": {"comune", "province"} in case files. Coordinates are those of
# spectra/comuni.csv (municipal seat), printed with the note.
assess_cli_test(spectrum_comune_laquila ARGS spectrum --comune "L'Aquila" --limit-state SLV
  PASS "comune L'Aquila \\(AQ\\), ISTAT 066049: lat 42\\.354, lon 13\\.392 \\(municipal seat\\).*Note *: municipal seat used")
assess_cli_test(spectrum_comune_bilingual ARGS spectrum --comune Bozen --limit-state SLV
  PASS "comune Bolzano \\(BZ\\), ISTAT 021008: lat 46\\.4981, lon 11\\.3548")
assess_cli_error_test(spectrum_comune_ambiguous "ambiguous: Castro \\(BG\\), ISTAT 016065, Castro \\(LE\\), ISTAT 075096; give the province"
  spectrum --comune Castro)
assess_cli_test(spectrum_comune_province ARGS spectrum --comune Castro --province LE --limit-state SLV
  PASS "comune Castro \\(LE\\), ISTAT 075096: lat 40\\.007, lon 18\\.4257")
assess_cli_error_test(spectrum_comune_unknown "did you mean L'Aquila \\(AQ\\)" spectrum --comune Lakuila)
assess_cli_error_test(spectrum_comune_and_lat "exactly one" spectrum --comune Roma --lat 41.9 --lon 12.5)
# The same lookup from a case file; an unknown comune names the JSON path.
assess_cli_test(run_site_comune ARGS run tests/cli/comuni/site_comune.json --lang en
  PASS "Site: comune L'Aquila \\(AQ\\), ISTAT 066049: lat 42\\.354, lon 13\\.392 \\(municipal seat\\).*Site given by comune: the coordinates of the municipal seat are used")
assess_cli_error_test(run_site_comune_ambiguous "/site/comune: comune 'Castro' is ambiguous"
  run tests/cli/comuni/ambiguous.json)
