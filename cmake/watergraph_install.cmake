# `cmake --install <build> --prefix P` installs the watergraph CLI, the compiler's headers and
# a CMake package so that a project can
#
#   find_package(watergraph CONFIG REQUIRED)      # CMAKE_PREFIX_PATH=P
#   watergraph_add_shaders(TARGET app GRAPHS water.json [TARGETS glsl330 es300 vk450 msl hlsl]
#                          [OUTPUT_DIR dir])
#
# Layout under P:
#   bin/watergraph
#   include/watergraph/{core,codegen,nodes}/*.h      (plus core/diagnostic_codes.def)
#   lib/cmake/watergraph/watergraphConfig.cmake, watergraphConfigVersion.cmake,
#     watergraphTargets.cmake (imported executable watergraph::watergraph),
#     WatergraphShaders.cmake (the function)
#   share/doc/watergraph/ (graph format, node reference, JSON Schema)
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(WG_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/watergraph)

install(TARGETS watergraph EXPORT watergraphTargets RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
foreach(dir core codegen nodes)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/watergraph/${dir}
          FILES_MATCHING PATTERN "*.h" PATTERN "*.def" PATTERN "glsl" EXCLUDE)
endforeach()
install(EXPORT watergraphTargets NAMESPACE watergraph:: DESTINATION ${WG_INSTALL_CMAKEDIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/watergraphConfig.cmake.in
  ${PROJECT_BINARY_DIR}/watergraphConfig.cmake
  INSTALL_DESTINATION ${WG_INSTALL_CMAKEDIR}
  PATH_VARS CMAKE_INSTALL_INCLUDEDIR CMAKE_INSTALL_BINDIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/watergraphConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/watergraphConfig.cmake ${PROJECT_BINARY_DIR}/watergraphConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/WatergraphShaders.cmake
        DESTINATION ${WG_INSTALL_CMAKEDIR})
install(FILES ${PROJECT_SOURCE_DIR}/docs/graph-format.md ${PROJECT_SOURCE_DIR}/docs/nodes.md
              ${PROJECT_SOURCE_DIR}/docs/watergraph.schema.json ${PROJECT_SOURCE_DIR}/docs/ecosystem.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR} OPTIONAL)

# The same function inside this build tree (for projects that add watergraph with
# add_subdirectory): watergraph::watergraph is the CLI target.
add_executable(watergraph::watergraph ALIAS watergraph)
include(${PROJECT_SOURCE_DIR}/cmake/WatergraphShaders.cmake)
