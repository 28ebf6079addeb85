# The backends of tools/backend.h (doc/backends.md): OpenGL through EGL
# against libsample's GL-exact filters, outside programs over the lookup
# protocol (tools/examples/bilinear.py), the tools' rows and errors. One
# process, so that llvmpipe starts once. Exit 77 where no OpenGL context can
# be made (no EGL in the build, no Mesa EGL driver on the machine).
if(TARGET texsample_backends AND TARGET texsample)
  add_executable(backends ${CMAKE_CURRENT_SOURCE_DIR}/backends.c)
  target_link_libraries(backends PRIVATE texsample_backends texsample_freq)
  target_include_directories(backends PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_options(backends PRIVATE ${SAMPLE_WARNINGS})
  add_test(NAME backends COMMAND backends $<TARGET_FILE:texsample>
           ${PROJECT_SOURCE_DIR}/tools/examples ${CMAKE_CURRENT_BINARY_DIR}/backends_out)
  # Mesa is not built with the sanitizers; its allocations at exit are not
  # ours to report (as for mesa_check).
  set_tests_properties(backends PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 120
    ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0")
endif()
