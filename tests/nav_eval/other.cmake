# `--buildings other:N:S` makes the kinds random:N:S never draws: labs and L-shaped corridors,
# named o<S>_<i> (fake_cogmap stands in for the runs). other:10:8001 draws both kinds (4 labs
# and 6 L-shaped corridors); each world's first line is the gen-building command that made it.
include(${CMAKE_CURRENT_LIST_DIR}/fake_run.cmake)
nav_eval_fake_run(other:10:8001 other)
set(labs 0)
set(ells 0)
foreach(i RANGE 1 10)
  generated_world_header(${out}/buildings/other_10_8001/o8001_${i}.world.yaml)
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
