# Run by ctest (tests/install_cli/CMakeLists.txt): install the cli component, draw with it, then
# take its render plugin away and check the refusal.
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --component cli --prefix ${prefix}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install --component cli failed")
endif()
set(cogmap ${prefix}/bin/cogmap)
set(plugin ${prefix}/${PLUGIN_DIR}/libcogmap_render_plugin.so)
foreach(f ${cogmap} ${plugin})
  if(NOT EXISTS ${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()

# The installed program, away from the build tree (COGMAP_PLUGIN_DIR unset): it must find the
# plugin beside itself.
set(ENV{COGMAP_PLUGIN_DIR} "")
execute_process(COMMAND ${cogmap} sonar-model --out ${WORK_DIR}/figs RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${WORK_DIR}/figs/echo_probability.png)
  message(FATAL_ERROR "the installed cogmap did not draw (${rc}): ${out}${err}")
endif()

# Without the plugin: exit 2, a message naming the plugin, and no figures.
file(RENAME ${plugin} ${plugin}.away)
execute_process(COMMAND ${cogmap} sonar-model --out ${WORK_DIR}/nofigs RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "cannot load the figure renderer.*libcogmap_render_plugin")
  message(FATAL_ERROR "without its plugin cogmap should exit 2 naming it; got ${rc}: ${err}")
endif()
if(EXISTS ${WORK_DIR}/nofigs/echo_probability.png)
  message(FATAL_ERROR "a figure was written without the renderer")
endif()
# A run that would draw stops before it writes anything.
execute_process(COMMAND ${cogmap} run ${SOURCE_DIR}/experiments/two_rooms.yaml --out ${WORK_DIR}/run
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "--no-figures" OR EXISTS ${WORK_DIR}/run/metrics.json)
  message(FATAL_ERROR "a run with figures but no renderer should exit 2 at once; got ${rc}: ${err}")
endif()
# Commands that draw nothing do not need it.
execute_process(COMMAND ${cogmap} --help RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cogmap --help failed without the render plugin (${rc})")
endif()
message(STATUS "install_cli: installed cogmap draws with its plugin and refuses (2) without it")
