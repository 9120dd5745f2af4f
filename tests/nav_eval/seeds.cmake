# Each generated building runs seeds of its own: the i-th building of a set runs --seeds A-B as
# 1000·i + A ... 1000·i + B, its run directories named by the seed run (the simulator's noise
# comes from the seed alone, so one seed for every building would give the whole set one noise
# stream); --shared-seeds runs every building with --seeds as given, and the shipped experiments
# always run --shipped-seeds as given. fake_cogmap writes the --seed it was given into DIR/seed.
function(check_runs out set expected)
  file(GLOB dirs LIST_DIRECTORIES true RELATIVE ${out}/runs/${set} ${out}/runs/${set}/*)
  list(SORT dirs)
  if(NOT "${dirs}" STREQUAL "${expected}")
    message(FATAL_ERROR "${set}: run directories ${dirs}, expected ${expected}")
  endif()
  foreach(d ${dirs})
    string(REGEX REPLACE ".*_s([0-9]+)$" "\\1" named ${d})
    file(STRINGS ${out}/runs/${set}/${d}/seed given)
    if(NOT given STREQUAL named)
      message(FATAL_ERROR "${set}/${d} was run with --seed ${given}")
    endif()
  endforeach()
endfunction()

function(evaluate out)
  file(REMOVE_RECURSE ${out})
  set(ENV{NAV_EVAL_FAKE_LOG} ${out}.log)
  execute_process(COMMAND ${PYTHON} ${SCRIPT} --buildings random:2:5 --seeds 1-2 ${ARGN}
                          --out ${out} --cogmap ${FAKE} --jobs 1
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "nav-eval ${ARGN} exited ${rc}: ${err}")
  endif()
endfunction()

evaluate(${WORK}/seeds_own)
check_runs(${WORK}/seeds_own random_2_5 "r5_1_s1001;r5_1_s1002;r5_2_s2001;r5_2_s2002")

evaluate(${WORK}/seeds_shared --shared-seeds)
check_runs(${WORK}/seeds_shared random_2_5 "r5_1_s1;r5_1_s2;r5_2_s1;r5_2_s2")

# The two kinds of evaluation are not mixed in one directory.
set(ENV{NAV_EVAL_FAKE_LOG} ${WORK}/seeds_own.log)
execute_process(COMMAND ${PYTHON} ${SCRIPT} --buildings random:2:5 --seeds 1-2 --shared-seeds
                        --out ${WORK}/seeds_own --cogmap ${FAKE} --jobs 1
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "were made with another seeds")
  message(FATAL_ERROR "shared seeds into a per-building evaluation: exit ${rc}: ${err}")
endif()
