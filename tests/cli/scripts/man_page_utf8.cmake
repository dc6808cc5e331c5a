# Issue 24: the man page keeps its UTF-8 text ("§3.2", "façade"; help2man's
# default C locale printed "??"). -DMAN=path to assess.1
file(READ ${MAN} man)
if(man MATCHES "\\?\\?")
  message(FATAL_ERROR "${MAN}: '??' in the man page (non-UTF-8 locale)")
endif()
if(NOT man MATCHES "façade" OR NOT man MATCHES "§3\\.2")
  message(FATAL_ERROR "${MAN}: 'façade' or '§3.2' missing")
endif()
