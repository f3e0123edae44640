# Bins the example data with `pgm discretize`, then runs the README's library example on it.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${PGM} discretize --in ${DATA} --columns xOff1,yOff1 --out ${WORK}/disc.csv
                COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND ${EXAMPLE} ${WORK}/disc.csv ${WORK}/fitted.bif COMMAND_ERROR_IS_FATAL ANY)
file(READ ${WORK}/fitted.bif bif)
if(NOT bif MATCHES "probability \\( onTop1 \\| xOff1, yOff1 \\)")
  message(FATAL_ERROR "fitted.bif lacks the table of onTop1:\n${bif}")
endif()
