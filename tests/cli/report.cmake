# The HTML/PDF relazione (issue 14). Each browser test writes a report, loads
# it in headless Chromium (tests/browser/check_html.sh: no console message,
# the expected number of figures with an SVG) and checks that the verdict box,
# the mechanism drawing, the ADRS plot and the tables are in the DOM. Skipped
# (exit 77) without chromium.
function(assess_report_browser_test name case figures)
  add_test(NAME cli.${name}
    COMMAND sh -c "out=$1; shift; exe=$1; shift; case=$1; shift; n=$1; shift; lang=$1; shift; \"$exe\" run \"$case\" --lang \"$lang\" --html \"$out\" > /dev/null && sh tests/browser/check_html.sh \"$out\" \"$n\" \"$@\""
            sh ${CMAKE_CURRENT_BINARY_DIR}/${name}.html $<TARGET_FILE:assess_cli> ${case} ${figures} ${ARGN}
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(cli.${name} PROPERTIES LABELS "cli;browser" SKIP_RETURN_CODE 77
    ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}")
endfunction()

set(_report_common
  "class=\"verdict (ok|fail)\" data-code=\"NTC2008\""
  "class=\"verdict (ok|fail)\" data-code=\"NTC2018\""
  "<figure id=\"fig-mechanism\"> ?<svg"
  "<figure id=\"fig-adrs\"> ?<svg"
  "<table class=\"checks\">"
  "<table> ?<caption>(Spostamenti virtuali|Virtual displacements)")
# Church (simple overturning with dynamics), Italian: 7 figures (spectra,
# mechanism, ADRS, moment-rotation, compatibility, histories, D/C bars).
assess_report_browser_test(report_church_it mechanisms/church-facade.json 7 it
  ${_report_common} "<html lang=\"it\"" "NON VERIFICATO" "verifica allo SLV"
  "<figure id=\"fig-compatibility\"> ?<svg" "<figure id=\"fig-histories\"> ?<div class=\"grid\">" "ribaltamento semplice"
  "<pre>[^<]*\"mechanism\"")
# The same in English.
assess_report_browser_test(report_church_en mechanisms/church-facade.json 7 en
  ${_report_common} "<html lang=\"en\"" "NOT SATISFIED" "simple overturning")
# A mechanism at height (gable above the eaves): its checks at height are in
# the table and the governing one in the verdict box.
assess_report_browser_test(report_gable_height mechanisms/gable.json 4 it
  ${_report_common} "Verifica che governa: verifica allo SL[VCD], [^<]*, in quota" "quota cerniera z = 7.00 m")

# PDF from the same HTML: the church report prints on 6 to 14 A4 pages
# (measured: 9). Skipped without chromium or pdfinfo (poppler-utils).
add_test(NAME cli.report_church_pdf
  COMMAND sh -c "command -v chromium >/dev/null && command -v pdfinfo >/dev/null || exit 77; \"$1\" run mechanisms/church-facade.json --pdf \"$2\" > /dev/null || exit 1; p=$(pdfinfo \"$2\" | sed -n 's/^Pages: *//p'); echo pages=$p; [ \"$p\" -ge 6 ] && [ \"$p\" -le 14 ] && pdfinfo \"$2\" | grep -q 'Page size:.*(A4)' "
          sh $<TARGET_FILE:assess_cli> ${CMAKE_CURRENT_BINARY_DIR}/church-report.pdf
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.report_church_pdf PROPERTIES LABELS "cli;browser" SKIP_RETURN_CODE 77
  ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}")
assess_cli_error_test(report_bad_lang "--lang 'fr': expected it .* or en" run mechanisms/free_wall_laquila.json --lang fr --html x.html)
