# `--buildings other:N:S` makes the kinds random:N:S never draws: labs and L-shaped corridors,
# named o<S>_<i> (fake_cogmap stands in for the runs). other:10:8001 draws both kinds (4 labs
# and 6 L-shaped corridors); each world's first line is the gen-building command that made it.
set(out ${WORK}/other)
file(REMOVE_RECURSE ${out})
set(ENV{NAV_EVAL_FAKE_LOG} ${WORK}/other.log)
execute_process(COMMAND ${PYTHON} ${SCRIPT} --buildings other:10:8001 --kind route --seeds 1
                        --out ${out} --cogmap ${FAKE} --jobs 1
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "nav-eval exited ${rc}: ${err}")
endif()
set(labs 0)
set(ells 0)
foreach(i RANGE 1 10)
  set(world ${out}/buildings/other_10_8001/o8001_${i}.world.yaml)
  if(NOT EXISTS ${world})
    message(FATAL_ERROR "no ${world}")
  endif()
  file(STRINGS ${world} lines LIMIT_COUNT 3)
  list(GET lines 0 command)
  list(GET lines 2 description)
  if(command MATCHES "gen-building lab " AND description MATCHES "m lab, desks and chairs")
    math(EXPR labs "${labs} + 1")
  elseif(command MATCHES "gen-building lcorridor --offices [2-7] " AND
         description MATCHES "^description: L-shaped")
    math(EXPR ells "${ells} + 1")
  else()
    message(FATAL_ERROR "o8001_${i}: neither a lab nor an L: ${command} / ${description}")
  endif()
endforeach()
if(NOT labs EQUAL 4 OR NOT ells EQUAL 6)
  message(FATAL_ERROR "other:10:8001 drew ${labs} labs and ${ells} L-shaped corridors, want 4 and 6")
endif()
