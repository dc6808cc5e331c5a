# Issue 24: a relazione is reproducible byte for byte: two runs of the same case
# write the same HTML (the Italian church report once printed a different number
# on every run, read from stray memory by a "%" in a message). Also checks that
# the record-selection sentence states the period range in increasing order.
# -DEXE=assess -DSRC=source dir -DOUT=scratch dir -DCASE=case file -DLANG=it|en
# Issue 36: the relazione and its tabulati, each run in a folder of its own (the
# two pages link each other by file name, so both runs write the same names).
foreach(i 1 2)
  file(MAKE_DIRECTORY ${OUT}/run${i})
  execute_process(COMMAND ${EXE} run ${CASE} --lang ${LANG} --html ${OUT}/run${i}/r.html
    RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err WORKING_DIRECTORY ${SRC})
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "assess run ${CASE} failed: ${err}")
  endif()
endforeach()
foreach(f r.html r-tabulati.html)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/run1/${f} ${OUT}/run2/${f} RESULT_VARIABLE same)
  if(NOT same EQUAL 0)
    message(FATAL_ERROR "two runs of ${CASE} (${LANG}) wrote different HTML (${f})")
  endif()
endforeach()
file(READ ${OUT}/run1/r.html html)
file(READ ${OUT}/run1/r-tabulati.html tab)
string(APPEND html "${tab}")
if(html MATCHES "(tra|over) ([0-9.,]+)( e |–)([0-9.,]+) s\\)")
  string(REPLACE "," "." lo "${CMAKE_MATCH_2}")
  string(REPLACE "," "." hi "${CMAKE_MATCH_4}")
  if(lo GREATER hi)
    message(FATAL_ERROR "selection period range reversed: ${CMAKE_MATCH_0}")
  endif()
  message(STATUS "selection range: ${CMAKE_MATCH_0}")
else()
  message(FATAL_ERROR "no record-selection sentence with its period range in the HTML")
endif()
message(STATUS "${CASE} (${LANG}): identical HTML in two runs")
