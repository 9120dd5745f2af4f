# `--buildings sized:N:S` makes buildings whose rooms are not 5 x 5 m: each one generated with
# gen-building --room-sizes-m, named s<S>_<i>, its description giving the range (fake_cogmap
# stands in for the runs).
include(${CMAKE_CURRENT_LIST_DIR}/fake_run.cmake)
nav_eval_fake_run(sized:3:9 sized)
foreach(i 1 2 3)
  generated_world_header(${out}/buildings/sized_3_9/s9_${i}.world.yaml)
  if(NOT command MATCHES "--room-sizes-m [0-9.]+-[0-9.]+")
    message(FATAL_ERROR "s9_${i} was made without --room-sizes-m: ${command}")
  endif()
  if(description MATCHES "5 x 5 m" OR NOT description MATCHES "of [0-9.]+-[0-9.]+ m")
    message(FATAL_ERROR "s9_${i}: ${description}")
  endif()
endforeach()
