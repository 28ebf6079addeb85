# The installed package: a fresh CMake project (find_package(libsample))
# and pkg-config builds, shared and static, each program run
# (install_test.sh), and the Python package imported from the prefix. Not
# under the sanitizers or the fuzzing build, whose
# libraries need the sanitizer runtimes in every program that links them.
if(NOT SAMPLE_SANITIZE AND NOT SAMPLE_TSAN AND NOT SAMPLE_FUZZ)
  set(_with_io OFF)
  if(TARGET sample_io_shared)
    set(_with_io ON)
  endif()
  add_test(NAME install_package
    COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/install_test.sh install ${PROJECT_BINARY_DIR}
      ${PROJECT_SOURCE_DIR} ${CMAKE_INSTALL_LIBDIR} ${CMAKE_C_COMPILER} ${_with_io}
      ${SAMPLE_PYTHON_INSTALL_DIR} "${SAMPLE_PYTHON3}" /usr/bin/python3)
  set_tests_properties(install_package PROPERTIES TIMEOUT 300)
endif()
# Only the public API is exported: the shared libraries' dynamic symbol
# tables hold exactly the functions the public headers mark SAMPLE_API /
# SAMPLE_IO_API / SAMPLE_MEASURE_API. Skipped (77) without nm.
set(_symbols_args ${PROJECT_SOURCE_DIR}/libsample/include/sample/sample.h
  $<TARGET_FILE:sample_shared> sample_)
if(TARGET sample_io_shared)
  # libsample_io: sample_io.h, and the texture system's own header.
  list(APPEND _symbols_args
    ${PROJECT_SOURCE_DIR}/libsample/io/include/sample/sample_io.h:${PROJECT_SOURCE_DIR}/libsample/io/include/sample/texsys.h
    $<TARGET_FILE:sample_io_shared> "sample_io_|sample_texsys_")
endif()
if(TARGET sample_measure)
  list(APPEND _symbols_args ${PROJECT_SOURCE_DIR}/tools/freq/sample_measure.h
    $<TARGET_FILE:sample_measure> sample_)
endif()
if(CMAKE_NM)
  set(_nm ${CMAKE_NM})
else()
  set(_nm nm)
endif()
add_test(NAME install_symbols
  COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/install_test.sh symbols ${_nm} ${_symbols_args})
set_tests_properties(install_symbols PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 60)
