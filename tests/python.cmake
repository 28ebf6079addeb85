# The Python package's tests (python/tests, pytest): one ctest entry, run by
# python/tests/run.sh with an interpreter that has numpy and pytest (the
# python3 found at configure time, else Debian's /usr/bin/python3), skipped
# (77) without one; and doc/python.md's example. The package is loaded from
# the source tree and finds the libraries of this build through
# LIBSAMPLE_LIBRARY_PATH. Not under the sanitizers or the fuzzing build:
# their libraries need the sanitizer runtime loaded before the interpreter
# starts.
if(NOT SAMPLE_SANITIZE AND NOT SAMPLE_TSAN AND NOT SAMPLE_FUZZ)
  set(_py_libs $<TARGET_FILE_DIR:sample_shared>)
  foreach(t sample_io_shared sample_measure)
    if(TARGET ${t})
      string(APPEND _py_libs ":$<TARGET_FILE_DIR:${t}>")
    endif()
  endforeach()
  set(_py_env "LIBSAMPLE_LIBRARY_PATH=${_py_libs}" "PYTHONPATH=${PROJECT_SOURCE_DIR}/python")
  if(TARGET texsample_cli)
    list(APPEND _py_env "LIBSAMPLE_TEXSAMPLE=$<TARGET_FILE:texsample_cli>")
  endif()
  add_test(NAME python COMMAND sh ${PROJECT_SOURCE_DIR}/python/tests/run.sh tests "${SAMPLE_PYTHON3}" /usr/bin/python3)
  set_tests_properties(python PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 120 ENVIRONMENT "${_py_env}")
  # The example measures with libsample_measure, under matplotlib's
  # file-only backend; skipped (77) where no interpreter has matplotlib
  # (install-deps.sh leaves it out: Debian's python3-matplotlib brings
  # SciPy, SymPy and Boost's headers, about forty packages).
  if(TARGET sample_measure)
    add_test(NAME python_example COMMAND sh ${PROJECT_SOURCE_DIR}/python/tests/run.sh example
      ${CMAKE_CURRENT_BINARY_DIR}/python_example.png "${SAMPLE_PYTHON3}" /usr/bin/python3)
    set_tests_properties(python_example PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 120
      ENVIRONMENT "${_py_env};MPLBACKEND=Agg")
  endif()
endif()
