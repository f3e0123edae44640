# Builds and runs tests/consumer against pgm, installed (MODE=find_package) or fetched
# (MODE=fetch_content). Invoked by ctest with PGM_SOURCE, PGM_BINARY, WORK and GENERATOR; it builds
# without optimization (no build type) on both cores, since it checks the packaging, not speed.
file(REMOVE_RECURSE ${WORK})
include(${CMAKE_CURRENT_LIST_DIR}/../support/run_checked.cmake)
if(MODE STREQUAL "find_package")
  run(${CMAKE_COMMAND} --install ${PGM_BINARY} --prefix ${WORK}/prefix)
  run(${CMAKE_COMMAND} -S ${PGM_SOURCE}/tests/consumer -B ${WORK}/build -G ${GENERATOR} -DCMAKE_PREFIX_PATH=${WORK}/prefix
      -DPGM_EXPECT_BULLET=${EXPECT_BULLET} -DPGM_TASK_FILE=${PGM_SOURCE}/tasks/drop-glass.json)
else()
  # A fetched pgm builds the Bullet back-end when asked (it is off below a top-level project).
  run(${CMAKE_COMMAND} -S ${PGM_SOURCE}/tests/consumer -B ${WORK}/build -G ${GENERATOR} -DPGM_FETCH_SOURCE=${PGM_SOURCE}
      -DPGM_BUILD_BULLET=${EXPECT_BULLET} -DPGM_EXPECT_BULLET=${EXPECT_BULLET} -DPGM_TASK_FILE=${PGM_SOURCE}/tasks/drop-glass.json)
endif()
run(${CMAKE_COMMAND} --build ${WORK}/build --parallel 2)
run(${WORK}/build/consumer)
run(${WORK}/build/consumer_core)
if(EXPECT_BULLET)
  run(${WORK}/build/consumer_bullet)
endif()
