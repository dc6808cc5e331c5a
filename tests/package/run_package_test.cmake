file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "install failed")
endif()
# Issue 31: the installed executable and MPI plugin have no RUNPATH that is
# empty (the current directory), relative or into the build tree.
find_program(READELF readelf)
if(READELF)
  file(GLOB installed ${WORK_DIR}/prefix/bin/assess ${WORK_DIR}/prefix/lib*/assess/assess_mpi.so
       ${WORK_DIR}/prefix/${PYTHON_DIR}/assess/_assess*.so)
  execute_process(COMMAND ${CMAKE_COMMAND} -DREADELF=${READELF} "-DFILES=${installed}" -DBUILD_DIR=${BUILD_DIR}
                  -P ${CMAKE_CURRENT_LIST_DIR}/../support/check_runpath.cmake RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "installed binaries: ${out}${err}")
  endif()
  message(STATUS "${out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build
                -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configure of the consumer failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "build of the consumer failed")
endif()
execute_process(COMMAND ${WORK_DIR}/build/consumer RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "consumer failed: ${out}")
endif()
message(STATUS "${out}")
# Issue 40: the installed Python package imports from its folder under the
# prefix and runs an analysis (a relative ASSESS_PYTHON_INSTALL_DIR only: an
# absolute one is outside the scratch prefix).
if(PYTHON AND NOT IS_ABSOLUTE "${PYTHON_DIR}")
  set(pydir ${WORK_DIR}/prefix/${PYTHON_DIR})
  if(NOT EXISTS ${pydir}/assess/__init__.py OR NOT EXISTS ${pydir}/assess/__init__.pyi)
    message(FATAL_ERROR "the Python package is not installed in ${pydir}/assess")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${pydir} PYTHONDONTWRITEBYTECODE=1 ${PYTHON} -c
    "import sys, assess; assert assess.__file__.startswith(sys.argv[1]), assess.__file__; r = assess.rocking('rigid', 0.25, 3.0, 12.06, [0.0, 0.5, 0.0, 0.0], dt=0.01); print('python: assess', assess.__version__, 'from', assess.__file__, r['termination'])"
    ${pydir} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the installed Python package: ${out}${err}")
  endif()
  message(STATUS "${out}")
endif()
