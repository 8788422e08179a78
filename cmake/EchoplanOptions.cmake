# Warnings and sanitizers shared by every echoplan target.
add_library(echoplan_options INTERFACE)
target_compile_options(echoplan_options INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor)
if(ECHOPLAN_SANITIZE)
  target_compile_options(echoplan_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
                                                    -fno-sanitize-recover=undefined)
  target_link_options(echoplan_options INTERFACE -fsanitize=address,undefined)
endif()

# echoplan_module(NAME SOURCES... DEPS ...): one static library per module, with src/ on the include
# path so headers are included as "module/header.h".
function(echoplan_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_library(echoplan_${name} STATIC ${ARG_SOURCES})
  target_include_directories(echoplan_${name} PUBLIC ${PROJECT_SOURCE_DIR}/src)
  target_link_libraries(echoplan_${name} PUBLIC ${ARG_DEPS} PRIVATE echoplan_options)
  add_library(echoplan::${name} ALIAS echoplan_${name})
endfunction()

# echoplan_test(NAME SOURCES... DEPS ...): one GoogleTest binary, registered with ctest.
function(echoplan_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gtest_main GTest::gmock echoplan_options)
  target_compile_definitions(${name} PRIVATE ECHOPLAN_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(${name} TEST_PREFIX "${name}." DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 300)
endfunction()
