# Python bindings (python/, docs/python.md): ONTILE_BUILD_PYTHON is on by default when pybind11
# and a Python with its development files are found. The interpreter defaults to Debian's
# /usr/bin/python3, which has the python3-numpy and python3-distributed packages the bindings
# and sweeps use (a pyenv `python3` earlier on PATH would not), so CI and developer machines
# build and test against the same interpreter.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python interpreter of the bindings and their tests")
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module QUIET)
if(Python3_FOUND)
  find_package(pybind11 CONFIG QUIET)
endif()
# Off in sanitizer builds: an instrumented extension cannot be loaded by an uninstrumented
# interpreter (the sanitizer runtime must come first), and those jobs test the C++ code.
if(Python3_FOUND AND pybind11_FOUND AND NOT ONTILE_SANITIZERS)
  set(_ontile_python_default ON)
else()
  set(_ontile_python_default OFF)
endif()
option(ONTILE_BUILD_PYTHON "Build the `ontile` Python module (pybind11) into build/python" ${_ontile_python_default})
