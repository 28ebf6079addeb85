# Direct OpenEXR reader of tiled mip-mapped files (doc/io-and-colour.md,
# "Tiled mip-mapped OpenEXR, read directly"). Uses the internal header to see
# which path a read took and to compare against the OIIO reader level by level.
# SAMPLE_IO_SAN_ENV and SAMPLE_MAKETX_ARG come from io.cmake, which
# tests/CMakeLists.txt includes first (file(GLOB) sorts: "io." < "io_").
if(TARGET sample_io)
  add_executable(io_exr_direct ${CMAKE_CURRENT_SOURCE_DIR}/io_exr_direct.c)
  target_link_libraries(io_exr_direct PRIVATE sample_io sample m)
  target_include_directories(io_exr_direct PRIVATE ${CMAKE_CURRENT_SOURCE_DIR} ${PROJECT_SOURCE_DIR}/libsample/io/src)
  target_compile_options(io_exr_direct PRIVATE ${SAMPLE_WARNINGS})
  set_target_properties(io_exr_direct PROPERTIES LINKER_LANGUAGE CXX)
  set(scratch ${CMAKE_CURRENT_BINARY_DIR}/io_exr_direct_scratch)
  add_test(NAME io_exr_direct COMMAND sh -c "rm -rf '${scratch}' && mkdir -p '${scratch}' && exec \"$0\" \"$@\""
    $<TARGET_FILE:io_exr_direct> ${PROJECT_SOURCE_DIR}/testimages ${scratch} "${SAMPLE_MAKETX_ARG}")
  # Without maketx (empty argument) its part is skipped: exit 77.
  set_tests_properties(io_exr_direct PROPERTIES TIMEOUT 300 SKIP_RETURN_CODE 77
    ENVIRONMENT "OCIO=;${SAMPLE_IO_SAN_ENV}")
endif()
