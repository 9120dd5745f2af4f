# `--buildings sized:N:S` makes buildings whose rooms are not 5 x 5 m: each one generated with
# gen-building --room-sizes-m, named s<S>_<i>, its description giving the range (fake_cogmap
# stands in for the runs).
set(out ${WORK}/sized)
file(REMOVE_RECURSE ${out})
set(ENV{NAV_EVAL_FAKE_LOG} ${WORK}/sized.log)
execute_process(COMMAND ${PYTHON} ${SCRIPT} --buildings sized:3:9 --kind route --seeds 1
                        --out ${out} --cogmap ${FAKE} --jobs 1
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "nav-eval exited ${rc}: ${err}")
endif()
foreach(i 1 2 3)
  set(world ${out}/buildings/sized_3_9/s9_${i}.world.yaml)
  if(NOT EXISTS ${world})
    message(FATAL_ERROR "no ${world}")
  endif()
  file(STRINGS ${world} lines LIMIT_COUNT 3)
  list(GET lines 0 command)
  list(GET lines 2 description)
  if(NOT command MATCHES "--room-sizes-m [0-9.]+-[0-9.]+")
    message(FATAL_ERROR "s9_${i} was made without --room-sizes-m: ${command}")
  endif()
  if(description MATCHES "5 x 5 m" OR NOT description MATCHES "of [0-9.]+-[0-9.]+ m")
    message(FATAL_ERROR "s9_${i}: ${description}")
  endif()
endforeach()
