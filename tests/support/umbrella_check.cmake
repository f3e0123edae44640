# Fails unless pgm/pgm.hpp includes every public header of include/pgm (all but detail/ and
# the optional adapters/), so that "everything in one include" stays true as headers are added.
#   cmake -DINCLUDE_DIR=<include> -P umbrella_check.cmake
file(READ "${INCLUDE_DIR}/pgm/pgm.hpp" umbrella)
file(GLOB_RECURSE headers RELATIVE "${INCLUDE_DIR}" "${INCLUDE_DIR}/pgm/*.hpp")
set(missing "")
foreach(header IN LISTS headers)
  if(header MATCHES "^pgm/(detail|adapters)/" OR header STREQUAL "pgm/pgm.hpp")
    continue()
  endif()
  string(FIND "${umbrella}" "#include \"${header}\"" at)
  if(at EQUAL -1)
    list(APPEND missing "${header}")
  endif()
endforeach()
if(missing)
  list(JOIN missing ", " missing)
  message(FATAL_ERROR "include/pgm/pgm.hpp does not include: ${missing}")
endif()
