# Whether the Python module `aloft` (host_sim/python/) is built: it needs Python 3 with its
# headers and NumPy, and pybind11, all from Debian (scripts/install-deps.sh host). Sets
# ALOFT_PYTHON_MODULE; without them the module is skipped with a message and the rest of
# the host build is the same.
set(ALOFT_PYTHON_MODULE OFF)
option(ALOFT_BUILD_PYTHON "Build the Python module aloft where Python 3, NumPy and pybind11 are found" ON)
if(NOT ALOFT_BUILD_PYTHON)
  message(STATUS "Python module aloft skipped: ALOFT_BUILD_PYTHON is OFF")
  return()
endif()
if(ALOFT_SANITIZE)
  # An ASan-built extension needs an ASan-built interpreter (or the runtime preloaded into
  # an uninstrumented one); Debian packages none: docs/python.md, "Tests".
  message(STATUS "Python module aloft skipped under ALOFT_SANITIZE: Debian has no ASan-instrumented Python")
  return()
endif()
# Debian's interpreter, whose python3-numpy, python3-pytest and python3-matplotlib
# install-deps.sh installs, before another python3 found first on PATH (pyenv, conda)
# that lacks them; -DPython3_EXECUTABLE=... chooses another.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python interpreter the module aloft is built for")
endif()
find_package(Python3 3.7 COMPONENTS Interpreter Development.Module NumPy)
if(NOT Python3_FOUND)
  message(STATUS "Python module aloft skipped: Python 3 with its headers and NumPy not found "
                 "(Debian: python3-dev python3-numpy; scripts/install-deps.sh host)")
  return()
endif()
# After Python3, so that pybind11 builds for that interpreter (its FindPython tools).
find_package(pybind11 2.6 CONFIG QUIET)
if(NOT pybind11_FOUND)
  message(STATUS "Python module aloft skipped: pybind11 not found (Debian: pybind11-dev; "
                 "scripts/install-deps.sh host)")
  return()
endif()
set(ALOFT_PYTHON_MODULE ON)
# For tests/python, a sibling directory: the interpreter the module is built for.
set(ALOFT_PYTHON_EXECUTABLE ${Python3_EXECUTABLE} CACHE INTERNAL "Python interpreter of the module aloft")
message(STATUS "Python module aloft: for ${Python3_EXECUTABLE} (${Python3_VERSION}), pybind11 ${pybind11_VERSION}")
