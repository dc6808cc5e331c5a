# Every bad tie field of a building (tests/cli/building_bad/ties_*.json: in a
# mechanism, in a wall's design, at the building level) exits with status 2
# and names the building file and the path IN THE BUILDING FILE of the bad
# field (issue 23 in a building case; docs/user/building.md).
file(GLOB cases ${SRC}/tests/cli/building_bad/ties_*.json)
list(LENGTH cases n)
if(n LESS 5)
  message(FATAL_ERROR "expected at least 5 bad building tie cases, found ${n}")
endif()
foreach(f ${cases})
  get_filename_component(name ${f} NAME)
  execute_process(COMMAND ${EXE} run ${f} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 2)
    message(FATAL_ERROR "${name}: expected exit 2, got ${rc}: ${err}")
  endif()
  if(NOT err MATCHES "building_bad/${name}: /(walls/[0-9]+/(mechanisms/[0-9]+/)?)?(ties|design)")
    message(FATAL_ERROR "${name}: the message does not name the building file and the building-file path: ${err}")
  endif()
  message(STATUS "ok ${name}: ${err}")
endforeach()
