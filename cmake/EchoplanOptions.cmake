# Warnings and sanitizers shared by every echoplan target.
add_library(echoplan_options INTERFACE)
target_compile_options(echoplan_options INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor)
if(ECHOPLAN_SANITIZE)
  target_compile_options(echoplan_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
                                                    -fno-sanitize-recover=undefined)
  target_link_options(echoplan_options INTERFACE -fsanitize=address,undefined)
endif()
if(ECHOPLAN_TSAN)
  if(ECHOPLAN_SANITIZE)
    message(FATAL_ERROR "ECHOPLAN_TSAN and ECHOPLAN_SANITIZE cannot be combined: build them apart")
  endif()
  target_compile_options(echoplan_options INTERFACE -fsanitize=thread -fno-omit-frame-pointer)
  target_link_options(echoplan_options INTERFACE -fsanitize=thread)
endif()

# echoplan_module(NAME SOURCES... DEPS ...): one static library per module, with src/ on the include
# path so headers are included as "module/header.h". Installed (cmake/EchoplanInstall.cmake) as
# echoplan::NAME with its headers under include/echoplan/<folder>/, so the same includes work in a
# project that uses find_package(echoplan). Link a dependency your public headers do not need PRIVATE.
include(GNUInstallDirs)
function(echoplan_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_library(echoplan_${name} STATIC ${ARG_SOURCES})
  target_include_directories(echoplan_${name} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src>
                                                     $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/echoplan>)
  target_link_libraries(echoplan_${name} PUBLIC ${ARG_DEPS} PRIVATE $<BUILD_INTERFACE:echoplan_options>)
  set_target_properties(echoplan_${name} PROPERTIES EXPORT_NAME ${name})
  add_library(echoplan::${name} ALIAS echoplan_${name})
  install(TARGETS echoplan_${name} EXPORT echoplanTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  set_property(GLOBAL APPEND PROPERTY ECHOPLAN_EXPORTED_MODULES ${name})
  file(RELATIVE_PATH folder ${PROJECT_SOURCE_DIR}/src ${CMAKE_CURRENT_SOURCE_DIR})
  file(GLOB headers CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.h)
  install(FILES ${headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/echoplan/${folder})
endfunction()

# Tests and benchmarks find the repository's files through tests/common/source_dir.h. The checkout's
# path is compiled into this one library, not passed to every compile: each test file then compiles
# the same in any folder, and a compiler cache filled from one clone hits from another.
function(echoplan_source_dir_library)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/source_dir.cpp.in ${PROJECT_BINARY_DIR}/source_dir.cpp @ONLY)
  add_library(echoplan_source_dir STATIC ${PROJECT_BINARY_DIR}/source_dir.cpp)
  target_include_directories(echoplan_source_dir PRIVATE ${PROJECT_SOURCE_DIR}/tests/common)
  target_link_libraries(echoplan_source_dir PRIVATE echoplan_options)
endfunction()

# echoplan_test(NAME SOURCES... DEPS ...): one GoogleTest binary, registered with ctest.
function(echoplan_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gtest_main GTest::gmock echoplan_options
                                        echoplan_source_dir)
  gtest_discover_tests(${name} TEST_PREFIX "${name}." DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 300)
endfunction()
