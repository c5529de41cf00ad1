# Installing ejecta (docs/install.md): `cmake --install build --prefix DIR` puts the `ejecta`
# binary, its shared libraries, their headers, a CMake package (find_package(ejecta), then
# target_link_libraries(app ejecta::sim)), the shipped scenes, the docs, the Python reader, the
# manual page and the bash completion under DIR; `cpack -G DEB` (in the build folder) makes a
# Debian package of the same tree.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# The installed binary finds its libraries next to it, wherever the tree is unpacked.
set(CMAKE_INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}")

set(EJECTA_INSTALL_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/ejecta)
set(EJECTA_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/ejecta)

# A library's headers: the source tree when built here (#include "sim/run/run.hpp"), the
# installed include/ejecta when found by find_package.
function(ejecta_library_includes target)
  get_target_property(type ${target} TYPE)
  set(scope PUBLIC)
  if(type STREQUAL "INTERFACE_LIBRARY")
    set(scope INTERFACE)
  endif()
  target_include_directories(${target} ${scope}
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}> $<INSTALL_INTERFACE:${EJECTA_INSTALL_INCLUDEDIR}>)
endfunction()

function(ejecta_install)
  set(libraries ejecta_core ejecta_sim ejecta_fields ejecta_radiation ejecta_render ejecta_coupling)
  foreach(lib ${libraries})
    string(REPLACE "ejecta_" "" short ${lib})
    set_target_properties(${lib} PROPERTIES EXPORT_NAME ${short})
  endforeach()
  install(TARGETS ${libraries} EXPORT ejectaTargets
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(TARGETS ejecta RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  foreach(dir core sim fields radiation render coupling)
    install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/ DESTINATION ${EJECTA_INSTALL_INCLUDEDIR}/${dir}
            FILES_MATCHING PATTERN "*.hpp")
  endforeach()
  install(EXPORT ejectaTargets NAMESPACE ejecta:: DESTINATION ${EJECTA_INSTALL_CMAKEDIR})
  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ejectaConfig.cmake.in
                                ${PROJECT_BINARY_DIR}/ejectaConfig.cmake
                                INSTALL_DESTINATION ${EJECTA_INSTALL_CMAKEDIR})
  write_basic_package_version_file(${PROJECT_BINARY_DIR}/ejectaConfigVersion.cmake
                                   VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
  install(FILES ${PROJECT_BINARY_DIR}/ejectaConfig.cmake ${PROJECT_BINARY_DIR}/ejectaConfigVersion.cmake
          DESTINATION ${EJECTA_INSTALL_CMAKEDIR})
  # The scenes are compiled into the binary (ejecta run NAME); the files are for copying.
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenes/ DESTINATION ${CMAKE_INSTALL_DATADIR}/ejecta/scenes)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)
  install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/python/ejecta DESTINATION ${CMAKE_INSTALL_DATADIR}/ejecta/python
          PATTERN "__pycache__" EXCLUDE)
  install(FILES ${PROJECT_BINARY_DIR}/apps/ejecta.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
  install(FILES ${PROJECT_BINARY_DIR}/apps/ejecta.bash-completion
          DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME ejecta)

  # cpack -G DEB: one package of the whole tree; its library dependencies from dpkg-shlibdeps.
  set(CPACK_PACKAGE_NAME ejecta)
  set(CPACK_PACKAGE_VENDOR "the ejecta developers")
  set(CPACK_PACKAGE_CONTACT "ejecta developers <ejecta@localhost>")
  set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "SPH hydrocode for hypervelocity impacts and explosions on asteroids")
  set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
  set(CPACK_GENERATOR DEB)
  set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
  set(CPACK_DEBIAN_PACKAGE_SECTION science)
  set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
  # The Python reader's dependencies, and the headers' (consumers compile against toml++).
  # The font is read at run time from its Debian path (render/outline_font.cpp).
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3-numpy, python3-h5py, libtomlplusplus-dev, fonts-dejavu-core")
  set(CPACK_DEBIAN_PACKAGE_SUGGESTS "python3-openvdb, python3-matplotlib, paraview")
  include(CPack)
endfunction()
