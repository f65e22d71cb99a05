# The installable package: `cmake --install build --prefix P` gives P/bin/ontile, the layer
# libraries in P/lib, their headers under P/include/ontile/<folder>/ (included as "<folder>/..."),
# the bundled scene and golden images in P/share/ontile, and P/lib/cmake/ontile/ontileConfig.cmake
# so that `find_package(ontile 0.4 REQUIRED)` gives the target ontile::ontile and the CLI as
# ontile::cli (README, "Install and use from another project").
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# The data folder the CLI looks for beside itself (apps/ontile/data_dir.cpp): <bin>/../share/ontile
# when installed, <build>/share/ontile in a build tree, where these links point into the sources.
# Nothing compiled names the source folder, so the binary can be moved and installed.
set(ONTILE_BUILD_DATA_DIR ${PROJECT_BINARY_DIR}/share/ontile)
file(MAKE_DIRECTORY ${ONTILE_BUILD_DATA_DIR})
foreach(link IN ITEMS "scenes|${PROJECT_SOURCE_DIR}/scenes" "golden|${PROJECT_SOURCE_DIR}/golden"
                      "assets|${PROJECT_SOURCE_DIR}/../shared/assets")
  string(REPLACE "|" ";" fields "${link}")
  list(GET fields 0 name)
  list(GET fields 1 target)
  if(NOT IS_SYMLINK ${ONTILE_BUILD_DATA_DIR}/${name})
    file(CREATE_LINK ${target} ${ONTILE_BUILD_DATA_DIR}/${name} SYMBOLIC)  # assets may not exist
  endif()
endforeach()

set(ONTILE_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/ontile)
set(ONTILE_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/ontile)

# The CLI is exported too, as ontile::cli, for tests such as add_test(COMMAND ontile::cli golden ...).
set_target_properties(ontile PROPERTIES EXPORT_NAME cli)
add_executable(ontile::cli ALIAS ontile)
get_property(ontile_layer_targets GLOBAL PROPERTY ONTILE_LAYER_TARGETS)
get_property(ontile_layer_folders GLOBAL PROPERTY ONTILE_LAYER_FOLDERS)
install(TARGETS ontile ${ontile_layer_targets} ontile_core EXPORT ontileTargets
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(folder IN LISTS ontile_layer_folders)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/${folder} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ontile
          FILES_MATCHING PATTERN "*.h")
endforeach()
install(FILES ${PROJECT_SOURCE_DIR}/scenes/demo.glb DESTINATION ${ONTILE_INSTALL_DATADIR}/scenes)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/golden DESTINATION ${ONTILE_INSTALL_DATADIR}
        FILES_MATCHING PATTERN "*.png")
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/CHANGELOG.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR})

install(EXPORT ontileTargets NAMESPACE ontile:: DESTINATION ${ONTILE_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ontileConfig.cmake.in
  ${PROJECT_BINARY_DIR}/ontileConfig.cmake INSTALL_DESTINATION ${ONTILE_INSTALL_CMAKEDIR}
  PATH_VARS ONTILE_INSTALL_DATADIR)
# 0.x releases change the API between minor versions: 0.4 accepts 0.4.*, not 0.5.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/ontileConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/ontileConfig.cmake ${PROJECT_BINARY_DIR}/ontileConfigVersion.cmake
        DESTINATION ${ONTILE_INSTALL_CMAKEDIR})
