# A set of buildings named twice is run once: each run directory gets one cogmap call (two
# would race for its lock). fake_cogmap logs every call.
set(out ${WORK}/set_twice)
file(REMOVE_RECURSE ${out})
file(REMOVE ${WORK}/set_twice.log)
set(ENV{NAV_EVAL_FAKE_LOG} ${WORK}/set_twice.log)
execute_process(COMMAND ${PYTHON} ${SCRIPT} --buildings random:2:5 --buildings random:2:5
                        --seeds 1-2 --out ${out} --cogmap ${FAKE} --jobs 2
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "nav-eval exited ${rc}: ${err}")
endif()
file(STRINGS ${WORK}/set_twice.log calls)
list(LENGTH calls n)
if(NOT n EQUAL 4)
  message(FATAL_ERROR "2 buildings x 2 seeds made ${n} cogmap calls, not 4: ${calls}")
endif()
