# Fails when a header of the library, or its definitions (impl/*.ipp), includes one of a module
# above its own. The modules from the bottom up; a module's files include their own module's
# and those of the modules below, never one above (a cycle starts so), and never an umbrella
# header (pgm/learn.hpp and the like, for users). detail holds the core's private helpers and
# pgm/config.hpp the build's settings: both sit with the core.
#   cmake -DINCLUDE_DIR=<include> -P layering_check.cmake
cmake_minimum_required(VERSION 3.20)
# Modules of one layer are written together, with commas.
set(layers
    "core,detail,config.hpp"
    "data"
    "inference"
    "learn"
    "transfer"
    "pipeline"
    "io"
    "causal"
    "decide"
    "sim"
    "eval"
    "adapters"
    "testing")

# The layer of a path below pgm/: its module's position in `layers`, -1 for none.
function(layer_of path result)
  string(REGEX MATCH "^[^/]+" module "${path}")
  set(position 0)
  foreach(layer IN LISTS layers)
    string(REPLACE "," ";" members "${layer}")
    if(module IN_LIST members)
      set(${result} ${position} PARENT_SCOPE)
      return()
    endif()
    math(EXPR position "${position} + 1")
  endforeach()
  set(${result} -1 PARENT_SCOPE)
endfunction()

file(GLOB_RECURSE files RELATIVE "${INCLUDE_DIR}/pgm" "${INCLUDE_DIR}/pgm/*.hpp" "${INCLUDE_DIR}/pgm/*.ipp")
list(FILTER files INCLUDE REGEX "/")  # the umbrellas at the top may include anything
set(problems "")
foreach(file IN LISTS files)
  layer_of("${file}" own)
  if(own EQUAL -1)
    string(REGEX MATCH "^[^/]+" module "${file}")
    list(APPEND problems "pgm/${file}: its module ${module}/ is not in the declared order (tests/support/layering_check.cmake)")
    continue()
  endif()
  file(STRINGS "${INCLUDE_DIR}/pgm/${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]+\"pgm/")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[^\"]*\"pgm/([^\"]+)\".*$" "\\1" target "${line}")
    if(NOT target MATCHES "/" AND NOT target STREQUAL "config.hpp")
      list(APPEND problems "pgm/${file} includes the umbrella pgm/${target}: include the headers it needs")
      continue()
    endif()
    layer_of("${target}" theirs)
    if(theirs GREATER own)
      list(APPEND problems "pgm/${file} includes pgm/${target}, from a module above its own")
    endif()
  endforeach()
endforeach()
list(LENGTH files count)
if(problems)
  list(JOIN problems "\n  " shown)
  message(FATAL_ERROR "the modules' order is broken:\n  ${shown}")
endif()
message(STATUS "${count} files of include/pgm keep the modules' order")
