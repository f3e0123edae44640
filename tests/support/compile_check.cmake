# Compiles one source alone, syntax only, and checks the outcome.
#   cmake -DCOMPILER=c++ "-DFLAGS=-std=c++20;-Iinclude" -DSOURCE=x.cpp -DEXPECT=fail -DMATCH=Concept
#         -P compile_check.cmake
# EXPECT=fail: the compiler must refuse SOURCE with a diagnostic that names MATCH (the concept).
# EXPECT=pass: SOURCE must compile; the compile-fail tests run it with PGM_CONTROL defined, which
# adds the one requirement the failing case leaves out, so that their failure is the concept's
# doing and not a mistake elsewhere in the file.
execute_process(COMMAND ${COMPILER} ${FLAGS} -fsyntax-only ${SOURCE}
                RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(EXPECT STREQUAL "pass")
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${SOURCE} should compile, but:\n${output}")
  endif()
elseif(EXPECT STREQUAL "fail")
  if(status EQUAL 0)
    message(FATAL_ERROR "${SOURCE} compiled, but the concept ${MATCH} should have refused it")
  endif()
  if(NOT output MATCHES "${MATCH}")
    message(FATAL_ERROR "${SOURCE} failed to compile, but no diagnostic names ${MATCH}:\n${output}")
  endif()
else()
  message(FATAL_ERROR "EXPECT must be pass or fail, got '${EXPECT}'")
endif()
