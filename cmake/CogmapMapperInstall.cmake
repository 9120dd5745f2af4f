# Install rules and the exported CMake package of the mapper (component `mapper`): the static
# libraries of mapper/ (and mapper/io when built), their public headers, and cogmapConfig.cmake
# so that find_package(cogmap COMPONENTS mapper) finds them. Included at the end of
# mapper/CMakeLists.txt, so it also works when mapper/ is built on its own.
include_guard(GLOBAL)
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

if(NOT DEFINED COGMAP_VERSION)
  set(COGMAP_VERSION 0.1.0)
endif()
set(cogmap_mapper_dir ${CMAKE_CURRENT_LIST_DIR}/../mapper)
set(cogmap_cmake_dest ${CMAKE_INSTALL_LIBDIR}/cmake/cogmap)

get_property(mapper_targets GLOBAL PROPERTY COGMAP_MAPPER_INSTALL_TARGETS)
install(TARGETS ${mapper_targets} EXPORT cogmap-mapper-targets COMPONENT mapper
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${cogmap_mapper_dir}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        COMPONENT mapper FILES_MATCHING PATTERN "*.h")
set(COGMAP_MAPPER_HAS_IO OFF)
if(TARGET cogmap_mapper_io)
  set(COGMAP_MAPPER_HAS_IO ON)
  install(DIRECTORY ${cogmap_mapper_dir}/io/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
          COMPONENT mapper FILES_MATCHING PATTERN "*.h")
endif()
install(EXPORT cogmap-mapper-targets NAMESPACE cogmap:: DESTINATION ${cogmap_cmake_dest}
        COMPONENT mapper)

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/cogmapConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/cogmap-package/cogmapConfig.cmake
                              INSTALL_DESTINATION ${cogmap_cmake_dest})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/cogmap-package/cogmapConfigVersion.cmake
                                 VERSION ${COGMAP_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/cogmap-package/cogmapConfig.cmake
              ${CMAKE_BINARY_DIR}/cogmap-package/cogmapConfigVersion.cmake
        DESTINATION ${cogmap_cmake_dest} COMPONENT mapper)
