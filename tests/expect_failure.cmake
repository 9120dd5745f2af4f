# Runs ${PYTHON} ${SCRIPT} ${ARGS} (ARGS a list: pass its separators as $<SEMICOLON>) and expects
# what bad input must give: exit 2 and an error matching ${PATTERN} (naming the file, line or
# option); with ${ABSENT}, also that the script did not create that path.
execute_process(COMMAND ${PYTHON} ${SCRIPT} ${ARGS} RESULT_VARIABLE rc OUTPUT_QUIET
                ERROR_VARIABLE err)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "${SCRIPT} ${ARGS} exited ${rc} (want 2): ${err}")
endif()
if(NOT err MATCHES "${PATTERN}")
  message(FATAL_ERROR "${SCRIPT} ${ARGS}: the error does not match '${PATTERN}': ${err}")
endif()
if(DEFINED ABSENT AND EXISTS ${ABSENT})
  message(FATAL_ERROR "${SCRIPT} ${ARGS} created ${ABSENT}")
endif()
