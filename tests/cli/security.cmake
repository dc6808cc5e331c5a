# Issue 31 (security): the loader never searches the current directory for
# the libraries of `assess`. The executable linked Open MPI with the RUNPATH
# "/usr/lib/x86_64-linux-gnu/openmpi/lib:" whose empty last entry is the
# current directory: a libgsl.so.27 planted there ran its code. Now the
# executable links no MPI (issue 32: the plugin assess_mpi.so) and has no
# RUNPATH; this test reads them (readelf -d) and refuses an empty, relative
# or build-tree entry; the package test checks the installed copies.
find_program(ASSESS_READELF readelf)
if(ASSESS_READELF)
  set(_sec_files $<TARGET_FILE:assess_cli>)
  if(TARGET assess_mpi)
    list(APPEND _sec_files $<TARGET_FILE:assess_mpi>)
  endif()
  add_test(NAME security.runpath
    COMMAND ${CMAKE_COMMAND} -DREADELF=${ASSESS_READELF} "-DFILES=${_sec_files}"
            -P ${CMAKE_CURRENT_SOURCE_DIR}/support/check_runpath.cmake)
  set_tests_properties(security.runpath PROPERTIES LABELS cli PASS_REGULAR_EXPRESSION "no empty, relative or build-tree")
endif()
# The same, as the attack: an empty (invalid) libgsl.so.27, libfmt.so.9 and
# libstdc++.so.6 in the current directory; `assess --version` must not load them.
set(_sec_dir ${PROJECT_BINARY_DIR}/tests/planted_libraries)
add_test(NAME security.planted_library
  COMMAND sh -c "rm -rf '${_sec_dir}' && mkdir -p '${_sec_dir}' && cd '${_sec_dir}' && : > libgsl.so.27 && : > libfmt.so.9 && : > libstdc++.so.6 && : > libgslcblas.so.0 && '$<TARGET_FILE:assess_cli>' --version")
set_tests_properties(security.planted_library PROPERTIES LABELS cli PASS_REGULAR_EXPRESSION "^assess [0-9]")
