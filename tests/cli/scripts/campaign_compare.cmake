# Runs a campaign twice into fresh directories and requires identical
# results.csv files. -DEXE=assess -DCAMPAIGN=file -DOUT=dir -DFIRST="launcher;args"
# -DSECOND="launcher;args" (each a prefix of the assess command: empty, or
# "mpirun;-np;2;..."), -DFIRST_ARGS / -DSECOND_ARGS (extra assess arguments).
# -DCOMMAND=fragility runs `assess fragility` on a case instead (default campaign).
if(NOT COMMAND)
  set(COMMAND campaign)
endif()
file(REMOVE_RECURSE ${OUT}/a ${OUT}/b)
execute_process(COMMAND ${FIRST} ${EXE} ${COMMAND} ${CAMPAIGN} --out ${OUT}/a --quiet --no-plots ${FIRST_ARGS}
  RESULT_VARIABLE rc1 OUTPUT_VARIABLE out1 ERROR_VARIABLE err1)
if(NOT rc1 EQUAL 0)
  message(FATAL_ERROR "first run failed (${rc1}): ${out1} ${err1}")
endif()
execute_process(COMMAND ${SECOND} ${EXE} ${COMMAND} ${CAMPAIGN} --out ${OUT}/b --quiet --no-plots ${SECOND_ARGS}
  RESULT_VARIABLE rc2 OUTPUT_VARIABLE out2 ERROR_VARIABLE err2)
if(NOT rc2 EQUAL 0)
  message(FATAL_ERROR "second run failed (${rc2}): ${out2} ${err2}")
endif()
message(STATUS "${out2}")
file(READ ${OUT}/a/results.csv a)
file(READ ${OUT}/b/results.csv b)
if(NOT a STREQUAL b)
  message(FATAL_ERROR "results.csv differ between the two runs")
endif()
string(REGEX MATCHALL "\n" lines "${a}")
list(LENGTH lines n)
message(STATUS "identical results.csv (${n} lines)")
file(REMOVE_RECURSE ${OUT}/a ${OUT}/b)
