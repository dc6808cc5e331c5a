# Issue 22: the building case (docs/user/building.md).
# Every mechanism of the example building (and of a second building with
# overrides, another site and soil) gives the numbers of its expanded
# single-mechanism case run alone; the governing mechanisms are recomputed
# from the single runs.
# Issue 23: building-house-ties (a wall's existing tie and its design, which
# act on every mechanism of the wall they cross, issue 37) also compares each
# mechanism's stato di fatto with the ties and the building's index
# before/after the ties.
foreach(b building-house:mechanisms/building-house.json chiesa_piccola:tests/cli/building/chiesa_piccola.json
          palazzo_sulmona:tests/cli/building/palazzo_sulmona.json building-house-ties:mechanisms/building-house-ties.json
          house_dynamic_two:tests/cli/building/house_dynamic_two.json)
  string(REPLACE ":" ";" parts ${b})
  list(GET parts 0 name)
  list(GET parts 1 file)
  add_test(NAME cli.building_vs_single_${name}
    COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/building_vs_single.py $<TARGET_FILE:assess_cli>
            ${PROJECT_SOURCE_DIR} ${file} ${CMAKE_CURRENT_BINARY_DIR}/building-expanded-${name}
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(cli.building_vs_single_${name} PROPERTIES LABELS cli TIMEOUT 300
    ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}")
endforeach()

# The terminal summary: every mechanism, the safety indices and the governing ones.
# The terminal summary (issue 41: the relazione's own sections, in the language of --lang).
assess_cli_test(building_text ARGS run mechanisms/building-house.json --lang en
  PASS "Outcome of the building's assessment.*2 of 10 mechanisms are not satisfied.*NTC 2018, linear \\(strength\\): M1 .*ζE = 0\\.561 \\(PGA_C.*TR_C = 104 years.*comune Norcia \\(PG\\).*M10 .*NTC 2008 \\(Circ\\. 617/2009 C8A\\.4\\), for comparison.*Records used")
assess_cli_test(building_json ARGS run mechanisms/building-house.json --json
  PASS "\"building\".*\"record_sets\".*\"governing\".*\"mechanisms\".*\"assessment\".*\"safety_indices\".*\"zeta_E\"")
# Issue 41: a warning every mechanism gives in the same words (the investigations' text names
# another knowledge level) is listed once in the building's warnings, with the ids that give it.
assess_cli_test(building_warning_once ARGS run tests/cli/building/house_dynamic_two.json --json
  PASS "names LC1 but the case adopts LC2 \\(FC = 1\\.20\\)[^\n]*correct the text or the key \\[M1, M2, M3, M4, M5, M6, M7, M8, M9, M10\\]\""
  FAIL_REGEX "correct the text or the key \\[M1 \"")
# One failing mechanism is said in the singular (Italian: "1 meccanismo su 10 non è verificato").
assess_cli_test(building_one_failing_it ARGS run tests/cli/building/house_dynamic_two.json
  PASS "1 meccanismo su 10 non è verificato con il metodo adottato[ |\n]+\\(M7\\)")
assess_cli_test(building_one_mechanism ARGS run mechanisms/building-house.json --mechanism M5 --lang en
  PASS "Ribaltamento del timpano.*Conclusion \\(adopted procedure.*gable about its base" FAIL_REGEX "building's assessment")

# Hostile input: every error names the file, the path in the building file and the unit; exit 2.
assess_cli_error_test(building_unknown_key "building_bad/unknown_key.json: /: unknown key \"knowlege_level\" \\(did you mean \"knowledge_level\"\\?\\)"
  run tests/cli/building_bad/unknown_key.json)
assess_cli_error_test(building_duplicate_name "duplicate_name.json: /walls/0/mechanisms/1/name: \"Overturning\": another mechanism"
  run tests/cli/building_bad/duplicate_name.json)
assess_cli_error_test(building_bad_thickness "bad_thickness.json: /walls/1/mechanisms/0/mechanism/storeys/0/thickness: expected a number \\(m\\)"
  run tests/cli/building_bad/bad_thickness.json)
assess_cli_error_test(building_fc_and_level "fc_and_level.json: /walls/0: give \"knowledge_level\" or \"FC\", not both"
  run tests/cli/building_bad/fc_and_level.json)
assess_cli_error_test(building_no_walls "no_walls.json: /walls: expected at least 1" run tests/cli/building_bad/no_walls.json)
assess_cli_error_test(building_bad_dynamic_override "bad_dynamic_override.json: /walls/0/mechanisms/0/dynamic/k: .*kN/m3"
  run tests/cli/building_bad/bad_dynamic_override.json)
assess_cli_error_test(building_no_site "no_site.json: /: missing required key \"site\"" run tests/cli/building_bad/no_site.json)
assess_cli_error_test(building_unknown_entry_key "unknown_entry_key.json: /walls/0/mechanisms/0: unknown key \"mechansim\" \\(did you mean \"mechanism\"\\?\\)"
  run tests/cli/building_bad/unknown_entry_key.json)
assess_cli_error_test(building_mechanisms_not_array "mechanisms_not_array.json: /walls/0/mechanisms: expected an array"
  run tests/cli/building_bad/mechanisms_not_array.json)
assess_cli_error_test(building_site_override "site_override.json: /walls/0/mechanisms/0: unknown key \"site\""
  run tests/cli/building_bad/site_override.json)
assess_cli_error_test(building_bad_Z_override "bad_Z_override.json: /walls/0/mechanisms/0/building/Z_m: expected a number \\(m\\)"
  run tests/cli/building_bad/bad_Z_override.json)
assess_cli_error_test(building_unknown_mechanism "no mechanism \"M9\" in the building \\(its mechanisms: M1 \"Facade overturning\", M2 \"Gable\""
  run tests/cli/building/chiesa_piccola.json --mechanism M9)
# Issue 23: bad tie rods in a building name the building file and the path in it; exit 2.
assess_cli_error_test(building_ties_bad_grade
  "ties_bad_grade.json: /walls/1/mechanisms/0/ties/0/rod/grade: \"S420\": expected one of \"S235\", \"S275\", \"S355\", \"B450C\" \\[M2 \"Side overturning\"\\]"
  run tests/cli/building_bad/ties_bad_grade.json)
assess_cli_error_test(building_ties_wall_design_fm
  "ties_wall_design_fm.json: /walls/0/design/ties/levels/0/masonry/fm_MPa: value -2 out of range: expected in \\[0\\.1, 50\\] MPa"
  run tests/cli/building_bad/ties_wall_design_fm.json)
assess_cli_error_test(building_ties_point_off_wall
  "ties_point_off_wall.json: /walls/0/mechanisms/0/ties/0/point: the anchor point .* is on no moving block"
  run tests/cli/building_bad/ties_point_off_wall.json)
assess_cli_error_test(building_ties_building_level
  "ties_building_level.json: /ties: \"ties\" is not a building-wide key"
  run tests/cli/building_bad/ties_building_level.json)
assess_cli_error_test(building_ties_design_no_levels
  "ties_design_no_levels.json: /walls/1/mechanisms/0/design/ties: missing required key \"levels\""
  run tests/cli/building_bad/ties_design_no_levels.json)
add_test(NAME cli.building_ties_exit2
  COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:assess_cli> -DSRC=${PROJECT_SOURCE_DIR}
          -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/building_ties_exit2.cmake
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.building_ties_exit2 PROPERTIES LABELS cli)
# The summary of a building with ties: each mechanism without and with its ties, the building index before/after,
# each mechanism's tie section; --mechanism runs the single case with its ties.
assess_cli_test(building_ties_text ARGS run mechanisms/building-house-ties.json --lang en
  PASS "Existing state: each mechanism with its existing ties.*M1 +Ribaltamento della facciata, +existing: 3 × Ø16 mm S275, plate 200 +0\\.531 +not satisfied.*Safety index of the building in the existing state \\(the smallest ζE of its mechanisms\\): 0\\.503 \\(M2\\).*M1 +Ribaltamento della facciata, +new: 6 × Ø12 mm S235, plate 300 × 300 +1\\.907 +satisfied +satisfied.*existing: removed.*Safety index of the building in the design state: 1\\.083 \\(M7\\)")
# Issue 37: the wall's existing eaves tie (0.2 m under the crown, threaded, 200 mm plates) fails; no new anchor
# keeps it from breaking, nor the designed rod through its holes: the least change is its removal.
assess_cli_test(building_ties_existing_removed ARGS run mechanisms/building-house-ties.json --mechanism M1 --lang en
  PASS "an existing tie that fails is changed by the least change.*Existing ties changed.*catena al sottotetto \\(esistente\\): removed.*Dynamic check in the existing and in the design state")
# The trials of the least change, in the JSON: a new anchor first, then a new rod through the same holes, then the removal.
assess_cli_test(building_ties_existing_trials ARGS run mechanisms/building-house-ties.json --mechanism M1 --json
  PASS "\"changes\": \"catena al sottotetto \\(esistente\\): new anchor: plate 150 x 150 x 12 mm S275\".*\"changes\": \"catena al sottotetto \\(esistente\\): new rod[^\"]*\".*\"changes\": \"catena al sottotetto \\(esistente\\): removed\".*\"outcome\": \"accepted\"")
assess_cli_test(building_ties_one_mechanism ARGS run mechanisms/building-house-ties.json --mechanism M2 --lang en
  PASS "catena al sottotetto \\(esistente\\) \\(existing state\\).*broken in 13 analyses of 14 \\(sliding of the masonry above the anchor\\).*sliding of the masonry above the anchor +designer's assumption +44\\.39 +15\\.99 +kN +2\\.777 +not satisfied" FAIL_REGEX "Summary of the assessment of the building")

assess_cli_error_test(building_expand_single "--mechanism and --expand apply to a building case"
  run mechanisms/gable.json --expand /tmp/never)

# The relazione of the example building in headless Chromium: loads without a
# console message, 12 figures in the body (the zetaE chart, the site spectra,
# each mechanism's drawing with ids prefixed by its id; issue 36: the ADRS
# plots and the dynamic figures are in the tabulati), the summary with a link
# to every mechanism's section, the sections themselves with their conclusion
# box and their links to the tabulati (Italian and English).
foreach(lang it en)
  add_test(NAME cli.building_report_browser_${lang}
    COMMAND sh -c "\"$1\" run mechanisms/building-house.json --lang $3 --html \"$2\" > /dev/null && sh tests/browser/check_html.sh \"$2\" 12 'id=\"summary\"' 'href=\"#M1\"' 'href=\"#M10\"' '<h2 id=\"M1\"' '<h2 id=\"M10\"' 'id=\"fig-zeta\"' 'id=\"M10-fig-mechanism\"' '★ [0-9]' 'class=\"box conclusion (ok|fail)\"' 'data-building=\"verdict\"' 'href=\"building-house.[a-z]*-tabulati.html#M10-cand-[0-9]+\"'"
            sh $<TARGET_FILE:assess_cli> ${CMAKE_CURRENT_BINARY_DIR}/building-house.${lang}.html ${lang}
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(cli.building_report_browser_${lang} PROPERTIES LABELS "cli;browser" SKIP_RETURN_CODE 77 TIMEOUT 300
    ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}")
endforeach()

# The relazione of the building with ties (Italian): the stato di fatto's and the stato di progetto's
# tables with one building index each, each tied mechanism's section with the mechanism in both states
# (ids prefixed by its id), the wall's ties once (issue 37: their levels drawn on the wall, the existing tie
# removed, each level's governing check per state; issue 36: 13 figures in the body, the 12 of
# building-house and the wall's drawing). Its tabulati: each mechanism's tie drawing, each level's wedge
# drawn against the crown and the full checks of every level in every mechanism (47 figures).
add_test(NAME cli.building_ties_report_browser
  COMMAND sh -c "\"$1\" run mechanisms/building-house-ties.json --html \"$2\" > /dev/null && sh tests/browser/check_html.sh \"$2\" 13 'id=\"wall1-ties-drawing\"' '<span class=\"secno\">[0-9.]*</span> Catene della parete Facciata su strada</h2>' '<span class=\"secno\">[0-9.]*</span> Catene esistenti modificate</h3>' 'Verifica più sfavorevole' 'catena al sottotetto \\(esistente\\)</span></td><td>stato di fatto</td><td>rottura nelle analisi dinamiche' 'Stato di fatto: ogni meccanismo con le sue catene esistenti' 'Indicatore di rischio dell.edificio nello stato di fatto[^<]*: 0,503 \\(M2\\)' 'Indicatore di rischio dell.edificio nello stato di progetto: 1,083 \\(M7\\)' && sh tests/browser/check_html.sh \"$3\" 47 'id=\"M1-ties-drawing\"' 'id=\"M2-ties-drawing\"' 'id=\"wall1-wall-wedge-1\"' 'catena al sottotetto \\(esistente\\) \\(stato di fatto\\)</h4>'"
          sh $<TARGET_FILE:assess_cli> ${CMAKE_CURRENT_BINARY_DIR}/building-house-ties.it.html
          ${CMAKE_CURRENT_BINARY_DIR}/building-house-ties.it-tabulati.html
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.building_ties_report_browser PROPERTIES LABELS "cli;browser" SKIP_RETURN_CODE 77 TIMEOUT 300
  ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}")

# `assess fragility BUILDING --mechanism M4` = `assess fragility` of M4's expanded case (identical results.csv);
# without --mechanism, the governing mechanism (lowest NTC 2018 zetaE of the adopted method's approach).
set(_bfrag ${PROJECT_BINARY_DIR}/tests/building_fragility)
add_test(NAME cli.building_fragility_mechanism
  COMMAND ${CMAKE_COMMAND} -E env ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}
          sh -c "rm -rf '${_bfrag}' && A='$<TARGET_FILE:assess_cli>' && F='--stripes 100,475,2475 --records 3 --bootstrap 0 --no-plots --quiet' && \"$A\" run mechanisms/building-house.json --expand '${_bfrag}/cases' > /dev/null && \"$A\" fragility mechanisms/building-house.json --mechanism M5 $F --out '${_bfrag}/b' && \"$A\" fragility '${_bfrag}/cases/M5.json' $F --out '${_bfrag}/s' > /dev/null && cmp '${_bfrag}/b/results.csv' '${_bfrag}/s/results.csv' && echo 'identical results.csv'"
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.building_fragility_mechanism PROPERTIES LABELS cli TIMEOUT 300
  PASS_REGULAR_EXPRESSION "fragility of 'gable about its base'.*identical results.csv")
add_test(NAME cli.building_fragility_governing
  COMMAND ${CMAKE_COMMAND} -E env ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}
          sh -c "rm -rf '${_bfrag}-gov' && '$<TARGET_FILE:assess_cli>' fragility mechanisms/building-house.json --stripes 100,2475 --records 3 --bootstrap 0 --no-plots --out '${_bfrag}-gov'"
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.building_fragility_governing PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "M2 \"Ribaltamento del secondo piano, cerniera al primo solaio\", the building's governing mechanism")
assess_cli_error_test(building_fragility_single "--mechanism applies to a building case"
  fragility mechanisms/gable.json --mechanism M1)
assess_cli_error_test(building_kinematic "a building case \\(key \"walls\"\\): `assess run mechanisms/building-house.json` analyses"
  kinematic mechanisms/building-house.json)

# The relazione printed to PDF (A4): summary and one section per mechanism.
add_test(NAME cli.building_report_pdf
  COMMAND sh -c "command -v chromium >/dev/null && command -v pdfinfo >/dev/null || exit 77; \"$1\" run mechanisms/building-house.json --pdf \"$2\" > /dev/null || exit 1; p=$(pdfinfo \"$2\" | sed -n 's/^Pages: *//p'); echo pages=$p; [ \"$p\" -ge 30 ] && [ \"$p\" -le 250 ] && pdfinfo \"$2\" | grep -q 'Page size:.*(A4)' "
          sh $<TARGET_FILE:assess_cli> ${CMAKE_CURRENT_BINARY_DIR}/building-house.pdf
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.building_report_pdf PROPERTIES LABELS "cli;browser" SKIP_RETURN_CODE 77 TIMEOUT 300
  ENVIRONMENT "ASSESS_DATA_DIR=${PROJECT_SOURCE_DIR}")
