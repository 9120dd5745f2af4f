# Runs ${PYTHON} ${SCRIPT} ${ARGS} (ARGS a list: pass its separators as $<SEMICOLON>) and
# compares what it prints with the file ${EXPECTED}: the scripts' tests on fixed inputs.
# WORKDIR, when given, is the directory it runs in (relative paths in ARGS and in the output).
if(NOT DEFINED WORKDIR)
  set(WORKDIR ${CMAKE_CURRENT_BINARY_DIR})
endif()
execute_process(COMMAND ${PYTHON} ${SCRIPT} ${ARGS} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                WORKING_DIRECTORY ${WORKDIR})
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${SCRIPT} exited ${rc}")
endif()
file(READ ${EXPECTED} expected)
if(NOT out STREQUAL expected)
  message(FATAL_ERROR "${SCRIPT} ${ARGS} printed:\n${out}\nexpected:\n${expected}")
endif()
