# `cmake --install BUILD [--prefix PREFIX]`: what a user of the program and of the library needs.
#   bin/hpcontact                                   the command line
#   lib/libhpcontact_<module>.a                     one static library per module (README.md, Layout);
#                                                   lib/<multiarch>/ for the prefix /usr (GNUInstallDirs)
#   include/hpcontact/<module>/*.hpp                their headers
#   lib/cmake/hpcontact/                            the CMake package: find_package(hpcontact)
#                                                   gives hpcontact::hpcontact (all modules) and
#                                                   hpcontact::<module>
#   lib/python3/dist-packages/hpcontact*.so         the Python module (HPC_PYTHON_INSTALL_DIR)
#   share/hpcontact/                                README.md, LICENSE, CITATION.cff, docs/,
#                                                   examples/ and scripts/ as in the repository
#                                                   (the docs' links and the scripts' default
#                                                   paths hold); the scripts start bin/hpcontact
#   share/doc/hpcontact/                            README.md, LICENSE, CITATION.cff
include(CMakePackageConfigHelpers)

set(HPC_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/hpcontact CACHE STRING
    "where the CMake package configuration is installed, relative to the prefix")
# Debian's layout: /usr/bin/python3 finds <prefix>/lib/python3/dist-packages on its own for the
# prefix /usr; for any other prefix, PYTHONPATH=<prefix>/lib/python3/dist-packages.
set(HPC_PYTHON_INSTALL_DIR lib/python3/dist-packages CACHE STRING
    "where the Python module is installed, relative to the prefix")

set(hpc_modules core geometry basis mesh material fem contact solve model analytic post adapt io driver)
set(hpc_library_targets hpcontact)
foreach(module ${hpc_modules})
  list(APPEND hpc_library_targets hpc_${module})
endforeach()

install(TARGETS hpcontact_app RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT program)
install(TARGETS ${hpc_library_targets} EXPORT hpcontactTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT library
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/hpcontact DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        COMPONENT library FILES_MATCHING PATTERN "*.hpp")
install(EXPORT hpcontactTargets NAMESPACE hpcontact:: DESTINATION ${HPC_CMAKE_INSTALL_DIR}
        COMPONENT library)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/hpcontactConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/hpcontactConfig.cmake
                              INSTALL_DESTINATION ${HPC_CMAKE_INSTALL_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/hpcontactConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/hpcontactConfig.cmake
              ${PROJECT_BINARY_DIR}/hpcontactConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/hpcontact_suitesparse.cmake
        DESTINATION ${HPC_CMAKE_INSTALL_DIR} COMPONENT library)

if(TARGET hpcontact_python)
  install(TARGETS hpcontact_python LIBRARY DESTINATION ${HPC_PYTHON_INSTALL_DIR} COMPONENT python)
endif()

set(hpc_share ${CMAKE_INSTALL_DATADIR}/hpcontact)
file(GLOB hpc_scripts ${PROJECT_SOURCE_DIR}/scripts/*.py)
install(PROGRAMS ${hpc_scripts} DESTINATION ${hpc_share}/scripts COMPONENT program)
set(hpc_front_files ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/LICENSE
                    ${PROJECT_SOURCE_DIR}/CITATION.cff)
install(FILES ${hpc_front_files} DESTINATION ${hpc_share} COMPONENT program)
install(FILES ${hpc_front_files} DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT program)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs ${PROJECT_SOURCE_DIR}/examples
        DESTINATION ${hpc_share} COMPONENT program USE_SOURCE_PERMISSIONS
        PATTERN "__pycache__" EXCLUDE PATTERN "*.pyc" EXCLUDE)

# A Debian package of the same tree: `cpack -G DEB` in the build folder (prefix /usr).
set(CPACK_PACKAGE_NAME hpcontact)
set(CPACK_PACKAGE_VENDOR "hpcontact")
set(CPACK_PACKAGE_CONTACT "hpcontact maintainers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "2D contact mechanics with high-order finite elements (h, p, hp, rp): program, library, Python module")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# What the headers, the CMake package and the scripts need beyond the shared libraries.
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "libeigen3-dev, libsuitesparse-dev, libyaml-cpp-dev, nlohmann-json3-dev, libmuparser-dev, python3, python3-numpy, python3-matplotlib, python3-yaml")
include(CPack)
