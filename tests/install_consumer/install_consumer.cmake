# Run by ctest (tests/install_consumer/CMakeLists.txt): install, build the consumer, run it.
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --component mapper --prefix ${prefix}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install --component mapper failed")
endif()
foreach(f lib/cmake/cogmap/cogmapConfig.cmake include/cogmap/mapper/mapper.h
          include/cogmap/mapper/seam/robot_models.h)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
if(EXISTS ${prefix}/bin/cogmap)
  message(FATAL_ERROR "the mapper component installed the CLI too")
endif()
set(disable -DCMAKE_DISABLE_FIND_PACKAGE_box2d=ON -DCMAKE_DISABLE_FIND_PACKAGE_yaml-cpp=ON
            -DCMAKE_DISABLE_FIND_PACKAGE_OpenGL=ON -DCMAKE_DISABLE_FIND_PACKAGE_PNG=ON)
# An ASan build's libraries need the sanitizer runtime in the consumer too.
if(SANITIZE)
  list(APPEND disable "-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined"
       "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${WORK_DIR}/build ${disable}
                        -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the consumer did not configure against the installed package")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the consumer did not build against the installed package")
endif()
execute_process(COMMAND ${WORK_DIR}/build/consumer OUTPUT_VARIABLE out RESULT_VARIABLE rc)
message(STATUS "consumer: ${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the consumer failed (${rc}): ${out}")
endif()
# A component that does not exist is refused by find_package.
execute_process(COMMAND ${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${WORK_DIR}/bad
                        -DCMAKE_PREFIX_PATH=${prefix} -DCONSUMER_COMPONENT=simulator
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT err MATCHES "no component 'simulator'")
  message(FATAL_ERROR "find_package accepted a component that does not exist: ${err}")
endif()
