# Cross-check against Mesa's softpipe through OSMesa (doc/mip-and-lod.md).
# Skips (exit 77) where no OSMesa 3.3 context can be made.
find_library(SAMPLE_OSMESA_LIBRARY OSMesa)
find_path(SAMPLE_OSMESA_INCLUDE GL/osmesa.h)
if(SAMPLE_OSMESA_LIBRARY AND SAMPLE_OSMESA_INCLUDE)
  add_executable(mesa_check ${CMAKE_CURRENT_SOURCE_DIR}/mesa_check.c ${CMAKE_CURRENT_SOURCE_DIR}/mesa_gl.c)
  target_link_libraries(mesa_check PRIVATE sample ${SAMPLE_OSMESA_LIBRARY})
  target_include_directories(mesa_check PRIVATE ${SAMPLE_OSMESA_INCLUDE})
  target_compile_options(mesa_check PRIVATE ${SAMPLE_WARNINGS})
  # POSIX mkdtemp, system.
  target_compile_definitions(mesa_check PRIVATE _POSIX_C_SOURCE=200809L)
  if(TARGET texsample)
    # Every configuration through the library; every 10th also through
    # `texsample lookup` (a process start each; the full run is
    # `mesa_check --texsample build/tools/texsample`).
    add_test(NAME mesa_check COMMAND mesa_check --texsample $<TARGET_FILE:texsample> --texsample-stride 10)
  else()
    add_test(NAME mesa_check COMMAND mesa_check)
  endif()
  # Mesa is not built with the sanitizers; its own allocations at exit are
  # not ours to report.
  set_tests_properties(mesa_check PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300
    ENVIRONMENT "GALLIUM_DRIVER=softpipe;ASAN_OPTIONS=detect_leaks=0")
  # Seamless cube maps against softpipe's (doc/environment-maps.md); reaches
  # into libsample/src for the face table.
  add_executable(mesa_cube ${CMAKE_CURRENT_SOURCE_DIR}/mesa_cube.c ${CMAKE_CURRENT_SOURCE_DIR}/mesa_gl.c)
  target_link_libraries(mesa_cube PRIVATE sample ${SAMPLE_OSMESA_LIBRARY})
  target_include_directories(mesa_cube PRIVATE ${SAMPLE_OSMESA_INCLUDE} ${PROJECT_SOURCE_DIR}/libsample/src)
  target_compile_options(mesa_cube PRIVATE ${SAMPLE_WARNINGS})
  target_compile_definitions(mesa_cube PRIVATE _POSIX_C_SOURCE=200809L)
  if(TARGET texsample_cli)
    # Every textureGrad state also through `texsample lookup --cube`: 18
    # starts of the front program, which reads raw files without loading
    # the image libraries (a few ms each).
    add_test(NAME mesa_cube COMMAND mesa_cube --texsample $<TARGET_FILE:texsample_cli>)
  else()
    add_test(NAME mesa_cube COMMAND mesa_cube)
  endif()
  set_tests_properties(mesa_cube PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300
    ENVIRONMENT "GALLIUM_DRIVER=softpipe;ASAN_OPTIONS=detect_leaks=0")
else()
  # Registered all the same, so that ctest reports the cross-check as
  # Skipped rather than leaving it out of the count.
  message(STATUS "OSMesa not found: mesa_check will report Skipped")
  add_test(NAME mesa_check COMMAND sh -c "echo 'SKIP: OSMesa (libosmesa6-dev) was not found when CMake configured this build'; exit 77")
  set_tests_properties(mesa_check PROPERTIES SKIP_RETURN_CODE 77)
  add_test(NAME mesa_cube COMMAND sh -c "echo 'SKIP: OSMesa (libosmesa6-dev) was not found when CMake configured this build'; exit 77")
  set_tests_properties(mesa_cube PROPERTIES SKIP_RETURN_CODE 77)
endif()
