# nav_eval_fake_run(SET NAME): scripts/nav-eval --buildings SET as routes, seed 1, into
# ${WORK}/NAME (set as `out` for the caller) with fake_cogmap standing in for the runs; a
# non-zero exit fails the test. For the cmake -P scripts that check what a set of buildings makes.
function(nav_eval_fake_run set name)
  set(dir ${WORK}/${name})
  file(REMOVE_RECURSE ${dir})
  set(ENV{NAV_EVAL_FAKE_LOG} ${WORK}/${name}.log)
  execute_process(COMMAND ${PYTHON} ${SCRIPT} --buildings ${set} --kind route --seeds 1
                          --out ${dir} --cogmap ${FAKE} --jobs 1
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "nav-eval exited ${rc}: ${err}")
  endif()
  set(out ${dir} PARENT_SCOPE)
endfunction()

# The first and third lines of a generated world: the gen-building command that made it and
# its description, into `command` and `description` for the caller.
function(generated_world_header world)
  if(NOT EXISTS ${world})
    message(FATAL_ERROR "no ${world}")
  endif()
  file(STRINGS ${world} lines LIMIT_COUNT 3)
  list(GET lines 0 first)
  list(GET lines 2 third)
  set(command ${first} PARENT_SCOPE)
  set(description ${third} PARENT_SCOPE)
endfunction()
