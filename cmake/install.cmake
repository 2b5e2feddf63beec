## ---------------------------------------------------------------------
## Installation and the CMake package qsmpm (included by the top-level
## CMakeLists.txt).
##
##   cmake --install build --prefix P
##
## installs
##   P/include/qsmpm/...                  the headers (with base/version.h)
##   P/lib/libqsmpm.so                    the library
##   P/bin/qsmpm                          the general driver
##   P/lib/cmake/qsmpm/qsmpmConfig.cmake  the package (+ ConfigVersion, Targets)
##   P/share/qsmpm/examples/<name>/       the examples' sources, .prm and data
##                                        files, each with a CMakeLists.txt
##   P/share/doc/qsmpm/                   doc/ and README.md, links rewritten
##                                        (cmake/install_doc_links.cmake)
##   P/share/doc/qsmpm/user_model/        tests/install_package/ (the user
##                                        model of doc/user_models.md)
##
## A user project then needs find_package(qsmpm) and
## target_link_libraries(app qsmpm::qsmpm); see doc/first_problem.md. The
## build tree is a package, too: -Dqsmpm_DIR=<this build directory>.
## ---------------------------------------------------------------------
include(CMakePackageConfigHelpers)

set(QSMPM_INSTALL_CMAKE_DIR lib/cmake/qsmpm)

# The installed driver program finds libqsmpm.so in ../lib, wherever the
# prefix is (the prefix is chosen only by `cmake --install --prefix`, after
# configuring); in the build tree CMake's build RPATH does the same. The
# launcher `qsmpm` links no library of its own.
# Both keep the directories of the libraries they link outside the system
# directories (a deal.II, MPI or HDF5 elsewhere) in their installed RPATH.
set_target_properties(qsmpm_driver_program PROPERTIES
  INSTALL_RPATH "$ORIGIN/../lib"
  INSTALL_RPATH_USE_LINK_PATH TRUE)
set_target_properties(qsmpm PROPERTIES
  INSTALL_RPATH_USE_LINK_PATH TRUE)
set_target_properties(qsmpm PROPERTIES EXPORT_NAME qsmpm)
set_target_properties(qsmpm_driver PROPERTIES EXPORT_NAME driver)
set_target_properties(qsmpm_driver_program PROPERTIES EXPORT_NAME driver_program)

install(TARGETS qsmpm qsmpm_driver qsmpm_driver_program
  EXPORT qsmpmTargets
  LIBRARY DESTINATION lib
  ARCHIVE DESTINATION lib
  RUNTIME DESTINATION bin)

# Headers: the sources' and the generated version.h.
install(DIRECTORY ${CMAKE_SOURCE_DIR}/include/ ${CMAKE_BINARY_DIR}/include/
  DESTINATION include
  FILES_MATCHING PATTERN "*.h")

# Examples, as deal.II installs its tutorial programs: every file of
# examples/<name>/ (sources, .prm files, plot scripts, the odf data of
# polycrystal) plus a CMakeLists.txt that builds the example against the
# installed package.
install(DIRECTORY ${CMAKE_SOURCE_DIR}/examples/
  DESTINATION share/qsmpm/examples
  PATTERN "output*" EXCLUDE)
foreach(_example ${QSMPM_EXAMPLES})
  if(EXISTS ${CMAKE_SOURCE_DIR}/examples/${_example}/${_example}.cc)
    set(QSMPM_EXAMPLE_NAME ${_example})
    configure_file(${CMAKE_SOURCE_DIR}/cmake/example_CMakeLists.txt.in
      ${CMAKE_BINARY_DIR}/example_cmake/${_example}/CMakeLists.txt @ONLY)
    install(FILES ${CMAKE_BINARY_DIR}/example_cmake/${_example}/CMakeLists.txt
      DESTINATION share/qsmpm/examples/${_example})
  endif()
endforeach()

# The documentation: doc/, the README next to its pages, and the user model
# of doc/user_models.md (the project of the test install_package); then the
# relative links of the installed pages are rewritten to the installed
# targets (cmake/install_doc_links.cmake; checked by the test
# installed_doc_links).
install(DIRECTORY ${CMAKE_SOURCE_DIR}/doc/ DESTINATION share/doc/qsmpm)
install(FILES ${CMAKE_SOURCE_DIR}/README.md DESTINATION share/doc/qsmpm)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/tests/install_package/
  DESTINATION share/doc/qsmpm/user_model)
# The example UMATs (Fortran and C) of doc/user_models.md, and the one of
# footing-umat.prm beside it.
install(DIRECTORY ${CMAKE_SOURCE_DIR}/tests/umat/
  DESTINATION share/doc/qsmpm/umat)
install(FILES ${CMAKE_SOURCE_DIR}/tests/umat/umat_von_mises.f
  DESTINATION share/qsmpm/examples/footing)
install(SCRIPT ${CMAKE_SOURCE_DIR}/cmake/install_doc_links.cmake)

# The package. qsmpmConfig.cmake is the same file in the build tree and in
# the installation: it finds deal.II (the installation used here first),
# then includes qsmpmTargets.cmake next to it.
set(QSMPM_DEAL_II_DIR "${deal.II_DIR}")
configure_file(${CMAKE_SOURCE_DIR}/cmake/qsmpmConfig.cmake.in
  ${CMAKE_BINARY_DIR}/qsmpmConfig.cmake @ONLY)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/qsmpmConfigVersion.cmake
  VERSION ${PROJECT_VERSION}
  COMPATIBILITY SameMajorVersion)

install(EXPORT qsmpmTargets
  NAMESPACE qsmpm::
  DESTINATION ${QSMPM_INSTALL_CMAKE_DIR})
install(FILES
  ${CMAKE_BINARY_DIR}/qsmpmConfig.cmake
  ${CMAKE_BINARY_DIR}/qsmpmConfigVersion.cmake
  DESTINATION ${QSMPM_INSTALL_CMAKE_DIR})

# The build tree as a package: -Dqsmpm_DIR=<build directory>.
export(EXPORT qsmpmTargets
  NAMESPACE qsmpm::
  FILE ${CMAKE_BINARY_DIR}/qsmpmTargets.cmake)
