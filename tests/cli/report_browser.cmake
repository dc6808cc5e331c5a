# Headless-Chromium check of the HTML report machinery: the self-test of
# tests/browser/check_html.sh renders a passing and a failing page and checks
# both verdicts. Skipped (exit 77) when Debian's chromium is not installed.
# Check a generated report with: tests/browser/check_html.sh FILE N_FIGURES
add_test(NAME cli.report_browser_selftest
  COMMAND sh ${PROJECT_SOURCE_DIR}/tests/browser/check_html.sh --self-test)
set_tests_properties(cli.report_browser_selftest PROPERTIES LABELS cli SKIP_RETURN_CODE 77)
