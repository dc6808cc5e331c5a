# Issue 24: a relazione is reproducible byte for byte: two runs of the same case
# write the same HTML (the Italian church report once printed a different number
# on every run, read from stray memory by a "%" in a message). Also checks that
# the record-selection sentence states the period range in increasing order.
# -DEXE=assess -DSRC=source dir -DOUT=scratch dir -DCASE=case file -DLANG=it|en
file(MAKE_DIRECTORY ${OUT})
foreach(i 1 2)
  execute_process(COMMAND ${EXE} run ${CASE} --lang ${LANG} --html ${OUT}/r${i}.html
    RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err WORKING_DIRECTORY ${SRC})
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "assess run ${CASE} failed: ${err}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/r1.html ${OUT}/r2.html RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "two runs of ${CASE} (${LANG}) wrote different HTML")
endif()
file(READ ${OUT}/r1.html html)
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
