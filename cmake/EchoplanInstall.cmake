# `cmake --install`: the echoplan binary, the shipped data, the module libraries with their headers and a
# CMake package, so another project can
#   find_package(echoplan REQUIRED)
#   target_link_libraries(app PRIVATE echoplan::pomdp echoplan::solvers echoplan::audio)
# (tests/install/ is such a project; scripts/check-install.sh builds it against a fresh install).
#
# Layout under the prefix:
#   bin/echoplan
#   share/echoplan/{problems,objects,experiments}/   found by the binary relative to itself (common/data_dir.h)
#   include/echoplan/<module>/*.h        included as "pomdp/model.h", as inside this repository
#   lib/libechoplan_<module>.a, lib/cmake/echoplan/
include(CMakePackageConfigHelpers)

set(ECHOPLAN_SHIPPED_DATA problems objects experiments)
install(TARGETS echoplan RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
foreach(folder IN LISTS ECHOPLAN_SHIPPED_DATA)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${folder} DESTINATION ${CMAKE_INSTALL_DATADIR}/echoplan)
endforeach()

# The build tree gets the installed layout too (build/share/echoplan/<folder> -> the source's folder), so
# build/echoplan finds the shipped data the same way the installed binary does, without a path compiled in.
foreach(folder IN LISTS ECHOPLAN_SHIPPED_DATA)
  file(MAKE_DIRECTORY ${PROJECT_BINARY_DIR}/share/echoplan)
  file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${folder} ${PROJECT_BINARY_DIR}/share/echoplan/${folder} SYMBOLIC)
endforeach()

set(ECHOPLAN_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/echoplan)
install(EXPORT echoplanTargets NAMESPACE echoplan:: DESTINATION ${ECHOPLAN_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/echoplanConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/echoplanConfig.cmake INSTALL_DESTINATION ${ECHOPLAN_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/echoplanConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/echoplanConfig.cmake ${PROJECT_BINARY_DIR}/echoplanConfigVersion.cmake
        DESTINATION ${ECHOPLAN_CMAKE_DIR})
