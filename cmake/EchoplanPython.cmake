# Whether the Python module `echoplan` (python/) is built: sets ECHOPLAN_PYTHON_MODULE.
#
# It is built when ECHOPLAN_BUILD_PYTHON is on (the default), Debian's pybind11 (pybind11-dev) and
# Python's headers (python3-dev) are found, and this is not the sanitizer build: an extension built
# with ASan only loads into a python3 started with libasan preloaded, so that build leaves it out
# rather than testing something no one runs.
#
# Debian's /usr/bin/python3 is preferred over another python3 earlier on PATH (pyenv, a venv): the
# module is installed where Debian's Python finds it and its tests need Debian's python3-numpy and
# python3-pytest. Pass -DPython3_EXECUTABLE=... to build for another interpreter.
set(ECHOPLAN_PYTHON_MODULE OFF)
if(ECHOPLAN_BUILD_PYTHON AND (ECHOPLAN_SANITIZE OR ECHOPLAN_TSAN))
  message(STATUS "Python module not built in the sanitizer build (it would need libasan preloaded)")
elseif(ECHOPLAN_BUILD_PYTHON)
  if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python3_EXECUTABLE /usr/bin/python3)
  endif()
  find_package(Python3 3.9 COMPONENTS Interpreter Development.Module)
  if(Python3_FOUND)
    find_package(pybind11 2.10 CONFIG QUIET)
  endif()
  if(Python3_FOUND AND pybind11_FOUND)
    set(ECHOPLAN_PYTHON_MODULE ON)
    # The module links the static module libraries into a shared object, which needs PIC code.
    # -fno-semantic-interposition keeps GCC's inlining as it is without PIC (no function of ours
    # is interposed), so the command's code and results do not change with the module.
    set(CMAKE_POSITION_INDEPENDENT_CODE ON)
    target_compile_options(echoplan_options INTERFACE -fno-semantic-interposition)
    message(STATUS "Python module: ${Python3_EXECUTABLE} (${Python3_VERSION}), pybind11 ${pybind11_VERSION}")
  else()
    message(STATUS "Python module not built: pybind11-dev or python3-dev not found (scripts/setup.sh installs them)")
  endif()
endif()
