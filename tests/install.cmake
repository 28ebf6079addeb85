# The installed package is usable from a fresh CMake project and via pkg-config.
if(NOT SAMPLE_SANITIZE AND NOT SAMPLE_TSAN)
  add_test(NAME install_package
    COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/install_test.sh ${PROJECT_BINARY_DIR} ${PROJECT_SOURCE_DIR})
  set_tests_properties(install_package PROPERTIES TIMEOUT 300)
endif()
