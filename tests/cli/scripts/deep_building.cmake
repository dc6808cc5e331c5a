# Issue 31: a building file nested 100 000 levels deep at WHERE (the project,
# the analysis section or the walls array) ended in a segmentation fault; it
# must be exit status 2 naming the file and the JSON path.
#   cmake -DEXE=assess -DWHERE=project -DWORK=dir -P deep_building.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(READ mechanisms/building-house.json text)
string(REPEAT "{\"a\":" 100000 open)
string(REPEAT "}" 100000 close)
# The deep value replaces the key's own value (the key stays first in the
# file); a key the file lacks ("analysis") is added first.
string(FIND "${text}" "\"${WHERE}\":" at)
if(at EQUAL -1)
  string(REGEX REPLACE "^[ \n]*{" "{\"${WHERE}\": ${open}1${close}," text "${text}")
else()
  string(REPLACE "\"${WHERE}\":" "\"${WHERE}\": ${open}1${close}, \"x_${WHERE}\":" text "${text}")
endif()
file(WRITE ${WORK}/deep.json "${text}")
execute_process(COMMAND ${EXE} run ${WORK}/deep.json RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "expected exit status 2, got ${rc}:\n${err}")
endif()
message(STATUS "${err}")
