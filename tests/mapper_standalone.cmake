# Configures mapper/ as its own project with the simulator, robot-driver and renderer
# dependencies disabled, builds the whole library and runs its end-to-end facade tests:
# any find_package of those packages fails, and with CMAKE_LINK_LIBRARIES_ONLY_TARGETS a
# library or test target that links to anything but a target (say `cogmap_sim`, which does
# not exist here) is a configure error, so a leak fails this test. The other mapper tests
# build and run in the main tree (their includes are checked by mapper_include_purity);
# building all of them again here took ~6 of scripts/test's ~7 minutes on 2 cores.
set(disable
    -DCMAKE_DISABLE_FIND_PACKAGE_box2d=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_yaml-cpp=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_OpenGL=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_PNG=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_PkgConfig=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON)
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${BINARY_DIR} ${disable}
                        -DCMAKE_BUILD_TYPE=Release -DCOGMAP_BENCHMARKS=OFF -DCMAKE_UNITY_BUILD=ON
                        -DCMAKE_LINK_LIBRARIES_ONLY_TARGETS=ON
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "mapper/ alone failed to configure")
endif()
include(ProcessorCount)
ProcessorCount(jobs)
# cogmap_mapper is an interface target: its parts are the facade (which pulls in every
# concept library but nav) and nav.
set(targets cogmap_mapper_facade cogmap_mapper_nav mapper_facade_test)
if(EXISTS ${BINARY_DIR}/io)  # the ASR store, when nlohmann-json was found
  list(APPEND targets cogmap_mapper_io)
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY_DIR} -j ${jobs} --target ${targets}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "mapper/ alone failed to build")
endif()
execute_process(COMMAND ${BINARY_DIR}/mapper_facade_test RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "mapper/ alone failed its facade tests")
endif()
