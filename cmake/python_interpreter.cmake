# The Python the module is built for: Python_EXECUTABLE if given, else the first python3 (on
# PATH, then /usr/bin/python3, Debian's) that can import numpy, which the module's tests and
# users need. Sets ASPERITY_PYTHON_FOUND and, when found, the Python:: targets (FindPython) and
# ASPERITY_PYTHON_INSTALL_DIR, the module's install folder (relative: under the prefix).
set(ASPERITY_PYTHON_FOUND OFF)
if(NOT Python_EXECUTABLE)
  find_program(ASPERITY_PYTHON_ON_PATH NAMES python3)
  foreach(candidate IN ITEMS "${ASPERITY_PYTHON_ON_PATH}" /usr/bin/python3)
    if(candidate AND EXISTS "${candidate}")
      execute_process(COMMAND "${candidate}" -c "import numpy" RESULT_VARIABLE has_numpy OUTPUT_QUIET ERROR_QUIET)
      if(has_numpy EQUAL 0)
        set(Python_EXECUTABLE "${candidate}" CACHE FILEPATH "The Python the asperity module is built for")
        break()
      endif()
    endif()
  endforeach()
endif()
if(NOT Python_EXECUTABLE)
  message(STATUS "asperity: no python3 that imports numpy: the Python module is not built "
                 "(scripts/setup.sh installs python3-numpy; or set Python_EXECUTABLE)")
  return()
endif()
find_package(Python 3.7 COMPONENTS Interpreter Development.Module)
if(Python_FOUND)
  find_package(pybind11 2.6 CONFIG QUIET)
endif()
if(NOT Python_FOUND OR NOT pybind11_FOUND)
  message(STATUS "asperity: the Python module needs the Python headers and pybind11 "
                 "(Debian: python3-dev, pybind11-dev): not built")
  return()
endif()
set(ASPERITY_PYTHON_FOUND ON)

# Where `cmake --install` puts the package: lib/pythonX.Y/<site-packages or dist-packages, as
# this interpreter names it> under the prefix. Under /usr/local or /usr that is on Debian's
# /usr/bin/python3 path; elsewhere PYTHONPATH names it.
execute_process(COMMAND "${Python_EXECUTABLE}" -c
                  "import sysconfig, os; print(os.path.basename(sysconfig.get_path('platlib')))"
                OUTPUT_VARIABLE site_folder OUTPUT_STRIP_TRAILING_WHITESPACE)
set(ASPERITY_PYTHON_INSTALL_DIR "lib/python${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}/${site_folder}"
    CACHE STRING "Where the Python package asperity is installed (relative: under the install prefix)")
