execute_process(
  COMMAND ${PYTHON} ${SCRIPT} --worst ${CSV} asr_count map.wall_error_median_m map.wall_coverage
          nav.route_completed timing.real_time_factor
  RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "summarize-sweep exited ${rc}")
endif()
file(READ ${EXPECTED} expected)
if(NOT out STREQUAL expected)
  message(FATAL_ERROR "summarize-sweep --worst printed:\n${out}\nexpected:\n${expected}")
endif()
