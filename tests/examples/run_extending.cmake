# Installs pgm into a temporary prefix, builds docs/examples/extending against it out of tree,
# runs every example and checks what it prints. Invoked by ctest with PGM_SOURCE, PGM_BINARY,
# WORK and GENERATOR.
file(REMOVE_RECURSE ${WORK})
include(${CMAKE_CURRENT_LIST_DIR}/../support/run_checked.cmake)

run(${CMAKE_COMMAND} --install ${PGM_BINARY} --prefix ${WORK}/prefix)
run(${CMAKE_COMMAND} -S ${PGM_SOURCE}/docs/examples/extending -B ${WORK}/build -G ${GENERATOR}
    -DCMAKE_PREFIX_PATH=${WORK}/prefix)
run(${CMAKE_COMMAND} --build ${WORK}/build --parallel 2)

# Each example and the lines its output must contain (regular expressions).
function(expect example)
  run(${CMAKE_COMMAND} -E env PGM_TASKS_DIR=${WORK}/prefix/share/pgm/tasks ${WORK}/build/${example})
  message(STATUS "${example}:\n${output}")
  foreach(pattern IN LISTS ARGN)
    if(NOT output MATCHES "${pattern}")
      message(FATAL_ERROR "${example} printed no line matching '${pattern}':\n${output}")
    endif()
  endforeach()
endfunction()

set(number "[0-9.e-]+")
expect(transfer_strategy "strategies: blend cross direct minimal\n" "blend: P\\(onTop2=1 \\| xOff1=0, xOff2=1\\) = 0.45\n")
expect(simulator_backend "back-ends: analytic ideal-drop\n"
       "drop-mug \\(analytic, seed 1\\): inside = 1 in ${number} of 20000 experiments\n"
       "drop-mug \\(ideal-drop, seed 1\\): inside = 1 in ${number} of 20000 experiments\n")
expect(task_file "tasks: drop-mug\n" "drop-mug: success 'inside', the robot controls xOff yOff\n"
       "P\\(inside = 1\\): exact ${number}, simulated ${number}\n"
       "a broken file: typo.json: /variables/0/kind: expected \"continuous\", \"categorical\" or \"outcome\"")
expect(scenario_file "Glass-To-Mug, Mean-Difference over 3 repetitions\n" "\\|D\\|\tmle\tdirect w=20\n"
       "\n0\t${number}\t${number}\n" "\n1000\t${number}\t${number}\n")
expect(parameter_prior "none: P\\(inside=1 \\| centre\\) = ${number}, P\\(inside=1 \\| corner\\) = ${number}\n"
       "centred: P\\(inside=1 \\| centre\\) = ${number}")
expect(inference_engine "engines: auto bp enumerate gibbs jt lw ve\n"
       "enumerate: P\\(rain=yes \\| grass=wet\\) = 0.413086, P\\(grass=wet\\) = 0.43618\n"
       "jt: P\\(rain=yes \\| grass=wet\\) = 0.413086, P\\(grass=wet\\) = 0.43618\n")
expect(conformance "\\[  PASSED  \\] 6 tests\\.")
expect(family_score "scores: aic\\[k=1\\] bdeu\\[iss=1\\] bic heavy-bic\\[weight=2\\] k2 loglik \n"
       "bic: a->c b->c\n" "heavy-bic\\[weight=3\\]: a->c\n")
expect(structure_learner "learners: chow-liu empty hc mmhc pc tabu\n" "hc: a->b b->c\n" "chow-liu: a->b b->c b->d\n"
       "chow-liu\\[min_information=0.01\\]: a->b b->c\n")
expect(network_format "formats: bif xmlbif net json uai fg\n" "files: .bif, .xml, .net, .json, .uai or .fg\n"
       "read back: 3 variables, 7 free parameters\n"
       "P\\(grass=wet \\| rain=yes, sprinkler=off\\) = 0.9, P\\(v2=1 \\| v0=1, v1=0\\) = 0.9\n"
       "a broken file: .*broken.fg:4:3: expected a variable's label, found 'x'")
