# `cmake --install BUILD --prefix P` (docs/own-bsdf.md):
#   P/bin/scatterlab                           the command line
#   P/include/scatterlab/{materials,validation,fitting,integrator}/...
#                                              every header of the four libraries; with
#                                              P/include/scatterlab on the include path a user
#                                              includes "materials/bsdf/bsdf.h" as the project does
#   P/lib/libscatterlab_*.a                    the libraries (position-independent: plugins link them)
#   P/lib/cmake/scatterlab/                    scatterlabConfig.cmake, its version file and the
#                                              exported targets scatterlab::materials, ::validation,
#                                              ::fitting, ::integrator and ::scatterlab (the executable)
#   P/share/scatterlab/                        run-time data (environment maps, the RGL measurements the
#                                              lab shows), example materials and sweeps
#   P/share/doc/scatterlab/examples/own-bsdf   the out-of-tree example
#   P/share/doc/scatterlab/examples/notebook.py the Python walk-through (docs/python.md)
# and a Debian package through CPack (`cpack -G DEB` in the build directory).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SCATTERLAB_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/scatterlab)

set_target_properties(scatterlab PROPERTIES EXPORT_NAME scatterlab)
install(TARGETS scatterlab_materials scatterlab_validation scatterlab_fitting scatterlab_integrator scatterlab
        EXPORT scatterlabTargets
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(library materials validation fitting integrator)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${library}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/scatterlab/${library}
          FILES_MATCHING PATTERN "*.h")
endforeach()
install(FILES ${PROJECT_BINARY_DIR}/generated/materials/registry/version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/scatterlab/materials/registry)
install(EXPORT scatterlabTargets NAMESPACE scatterlab:: DESTINATION ${SCATTERLAB_INSTALL_CMAKEDIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/scatterlabConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/scatterlabConfig.cmake
                              INSTALL_DESTINATION ${SCATTERLAB_INSTALL_CMAKEDIR})
# Plugins carry an ABI stamp with the exact version (materials/registry/plugin.h); code built
# against 0.1.x compiles against any 0.1.y.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/scatterlabConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/scatterlabConfig.cmake ${PROJECT_BINARY_DIR}/scatterlabConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/scatterlabPlugin.cmake
        DESTINATION ${SCATTERLAB_INSTALL_CMAKEDIR})

install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/envmaps ${PROJECT_SOURCE_DIR}/data/materials ${PROJECT_SOURCE_DIR}/data/rgl
                  ${PROJECT_SOURCE_DIR}/data/sweeps
        DESTINATION ${CMAKE_INSTALL_DATADIR}/scatterlab)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/own-bsdf DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples)
install(FILES ${PROJECT_SOURCE_DIR}/examples/notebook.py DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples)

# A .deb of the same tree; its dependencies are the Debian packages scripts/setup installs for
# the libraries a user links (headers included) and the run-time libraries of the executable.
set(CPACK_PACKAGE_NAME scatterlab)
set(CPACK_PACKAGE_VENDOR "scatterlab")
set(CPACK_PACKAGE_CONTACT "scatterlab maintainers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "libglm-dev, nlohmann-json3-dev, libeigen3-dev, libtbb-dev, libceres-dev, libopenexr-dev, libpng-dev")
include(CPack)
