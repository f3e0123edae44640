# The peers the agreement tests compare with (pgmpy and the opt_einsum it imports), as source:
# PyPI is out of reach, so their tarballs sit in ../shared/peers beside the checkout (or in
# PGM_PEERS_DIR). When found, they are unpacked into the build tree once and put on the path
# the tests give Debian's python3, unless PGM_PGMPY_PATH is set already. Without them the tests
# that need pgmpy are not registered, with a message saying so (CI has them and checks that the
# tests are registered).
set(PGM_PEERS_DIR "${PROJECT_SOURCE_DIR}/../shared/peers" CACHE PATH
    "Where the peers' source tarballs are (pgmpy-*.tar.gz, opt_einsum-*.tar.gz)")
set(PGM_PGMPY_PATH "" CACHE STRING "PYTHONPATH under which Debian's python3 imports pgmpy, for the agreement tests")
if(PGM_PGMPY_PATH STREQUAL "")
  file(GLOB pgm_pgmpy_tarball "${PGM_PEERS_DIR}/pgmpy-*.tar.gz")
  file(GLOB pgm_einsum_tarball "${PGM_PEERS_DIR}/opt_einsum-*.tar.gz")
  if(pgm_pgmpy_tarball AND pgm_einsum_tarball)
    set(pgm_peers_unpacked "${PROJECT_BINARY_DIR}/peers")
    if(NOT EXISTS "${pgm_peers_unpacked}/pgmpy-head/pgmpy/__init__.py")
      message(STATUS "Unpacking pgmpy and opt_einsum from ${PGM_PEERS_DIR} into ${pgm_peers_unpacked}")
      file(ARCHIVE_EXTRACT INPUT ${pgm_pgmpy_tarball} DESTINATION "${pgm_peers_unpacked}")
      file(ARCHIVE_EXTRACT INPUT ${pgm_einsum_tarball} DESTINATION "${pgm_peers_unpacked}")
    endif()
    set(PGM_PGMPY_PATH "${pgm_peers_unpacked}/pgmpy-head:${pgm_peers_unpacked}/pylib" CACHE STRING
        "PYTHONPATH under which Debian's python3 imports pgmpy, for the agreement tests" FORCE)
  else()
    message(STATUS "No pgmpy and opt_einsum tarballs in ${PGM_PEERS_DIR} (PGM_PEERS_DIR): the agreement tests "
                   "with pgmpy run only where PGM_PGMPY_PATH names an unpacked pgmpy")
  endif()
endif()

# Whether Debian's python3 imports pgmpy under PGM_PGMPY_PATH: one probe for the C++ and the Python
# agreement tests alike, run again only when the path changes (importing pgmpy takes a while).
# A failed import is reported with Python's own message, so a log says why the tests are missing.
if(NOT DEFINED PGM_PGMPY_FOUND OR NOT "${PGM_PGMPY_FOUND_FOR}" STREQUAL "${PGM_PGMPY_PATH}")
  set(pgm_pgmpy_found OFF)
  if(NOT PGM_PGMPY_PATH STREQUAL "" AND EXISTS /usr/bin/python3)
    # Twice at most: a first import may fail where it only sets up caches (byte code, fonts).
    foreach(pgm_pgmpy_attempt RANGE 1)
      execute_process(COMMAND ${CMAKE_COMMAND} -E env "PYTHONPATH=${PGM_PGMPY_PATH}" /usr/bin/python3 -c "import pgmpy"
                      RESULT_VARIABLE pgm_pgmpy_status OUTPUT_QUIET ERROR_VARIABLE pgm_pgmpy_error TIMEOUT 600)
      if(pgm_pgmpy_status EQUAL 0)
        break()
      endif()
    endforeach()
    if(pgm_pgmpy_status EQUAL 0)
      set(pgm_pgmpy_found ON)
    else()
      string(LENGTH "${pgm_pgmpy_error}" pgm_pgmpy_error_length)
      if(pgm_pgmpy_error_length GREATER 2000)
        math(EXPR pgm_pgmpy_error_start "${pgm_pgmpy_error_length} - 2000")
        string(SUBSTRING "${pgm_pgmpy_error}" ${pgm_pgmpy_error_start} -1 pgm_pgmpy_error)
      endif()
      message(STATUS "/usr/bin/python3 does not import pgmpy under PYTHONPATH='${PGM_PGMPY_PATH}' "
                     "(${pgm_pgmpy_status}):\n${pgm_pgmpy_error}")
    endif()
  endif()
  set(PGM_PGMPY_FOUND ${pgm_pgmpy_found} CACHE INTERNAL "Debian's python3 imports pgmpy under PGM_PGMPY_PATH")
  set(PGM_PGMPY_FOUND_FOR "${PGM_PGMPY_PATH}" CACHE INTERNAL "PGM_PGMPY_PATH when pgmpy was probed")
endif()

# R bnlearn, for tests/peers/bnlearn_agreement_test.cpp: where its source tarball is in
# PGM_PEERS_DIR and Rscript runs, it is installed once into the build tree (R CMD INSTALL, about
# 20 s) and PGM_BNLEARN_LIB names the library folder; otherwise the test is not registered.
set(PGM_BNLEARN_LIB "" CACHE PATH "R library folder where bnlearn is installed, for the agreement tests")
if(PGM_BNLEARN_LIB STREQUAL "")
  file(GLOB pgm_bnlearn_tarball "${PGM_PEERS_DIR}/bnlearn-*-src.tar.gz")
  find_program(PGM_RSCRIPT Rscript)
  find_program(PGM_R R)
  if(pgm_bnlearn_tarball AND PGM_RSCRIPT AND PGM_R)
    set(pgm_bnlearn_lib "${PROJECT_BINARY_DIR}/peers/bnlearn-lib")
    if(NOT EXISTS "${pgm_bnlearn_lib}/bnlearn/DESCRIPTION")
      message(STATUS "Installing R bnlearn from ${pgm_bnlearn_tarball} into ${pgm_bnlearn_lib}")
      file(ARCHIVE_EXTRACT INPUT ${pgm_bnlearn_tarball} DESTINATION "${PROJECT_BINARY_DIR}/peers")
      file(MAKE_DIRECTORY "${pgm_bnlearn_lib}")
      execute_process(COMMAND ${PGM_R} CMD INSTALL -l "${pgm_bnlearn_lib}" "${PROJECT_BINARY_DIR}/peers/bnlearn-src"
                      RESULT_VARIABLE pgm_bnlearn_status OUTPUT_QUIET ERROR_VARIABLE pgm_bnlearn_error TIMEOUT 1200)
      if(NOT pgm_bnlearn_status EQUAL 0)
        message(STATUS "R CMD INSTALL bnlearn failed (${pgm_bnlearn_status}): ${pgm_bnlearn_error}")
      endif()
    endif()
    if(EXISTS "${pgm_bnlearn_lib}/bnlearn/DESCRIPTION")
      set(PGM_BNLEARN_LIB "${pgm_bnlearn_lib}" CACHE PATH
          "R library folder where bnlearn is installed, for the agreement tests" FORCE)
    endif()
  elseif(NOT pgm_bnlearn_tarball)
    message(STATUS "No bnlearn-*-src.tar.gz in ${PGM_PEERS_DIR}: the agreement tests with R bnlearn are not "
                   "registered")
  else()
    message(STATUS "No Rscript: the agreement tests with R bnlearn are not registered (install r-base-core)")
  endif()
endif()
