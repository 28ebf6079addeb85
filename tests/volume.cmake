# 3D textures beyond the library's own test (test_volume.c): texsample
# lookup --volume end to end.
if(TARGET texsample_cli)
  add_executable(cli_volume ${CMAKE_CURRENT_SOURCE_DIR}/cli_volume.c)
  target_link_libraries(cli_volume PRIVATE sample)
  target_include_directories(cli_volume PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_options(cli_volume PRIVATE ${SAMPLE_WARNINGS})
  add_test(NAME cli_volume COMMAND cli_volume $<TARGET_FILE:texsample_cli>)
  set_tests_properties(cli_volume PROPERTIES TIMEOUT 60)
endif()
# 3D textures against Mesa's softpipe (GL_TEXTURE_3D, textureGrad and
# textureLod): skips (77) where no OSMesa 3.3 context can be made, as
# mesa_check (tests/mesa.cmake finds OSMesa). Every 8th configuration also
# through `texsample lookup --volume` (the front program).
if(SAMPLE_OSMESA_LIBRARY AND SAMPLE_OSMESA_INCLUDE)
  add_executable(mesa_volume ${CMAKE_CURRENT_SOURCE_DIR}/mesa_volume.c ${CMAKE_CURRENT_SOURCE_DIR}/mesa_gl.c)
  target_link_libraries(mesa_volume PRIVATE sample ${SAMPLE_OSMESA_LIBRARY})
  target_include_directories(mesa_volume PRIVATE ${SAMPLE_OSMESA_INCLUDE} ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_options(mesa_volume PRIVATE ${SAMPLE_WARNINGS})
  # POSIX mkdtemp.
  target_compile_definitions(mesa_volume PRIVATE _POSIX_C_SOURCE=200809L)
  if(TARGET texsample_cli)
    add_test(NAME mesa_volume COMMAND mesa_volume --texsample $<TARGET_FILE:texsample_cli> --texsample-stride 8)
  else()
    add_test(NAME mesa_volume COMMAND mesa_volume)
  endif()
  set_tests_properties(mesa_volume PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300
    ENVIRONMENT "GALLIUM_DRIVER=softpipe;ASAN_OPTIONS=detect_leaks=0")
else()
  add_test(NAME mesa_volume COMMAND sh -c "echo 'SKIP: OSMesa (libosmesa6-dev) was not found when CMake configured this build'; exit 77")
  set_tests_properties(mesa_volume PROPERTIES SKIP_RETURN_CODE 77)
endif()
# Volume images through libsample_io (oiiotool makes them: skipped, 77,
# without it; tests/io.cmake finds it).
if(TARGET sample_io)
  add_executable(io_volume ${CMAKE_CURRENT_SOURCE_DIR}/io_volume.c)
  target_link_libraries(io_volume PRIVATE sample_io sample m)
  target_include_directories(io_volume PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_options(io_volume PRIVATE ${SAMPLE_WARNINGS})
  set(scratch ${CMAKE_CURRENT_BINARY_DIR}/io_volume_scratch)
  if(TARGET texsample_cli)
    set(_texsample $<TARGET_FILE:texsample_cli>)
  else()
    set(_texsample "")
  endif()
  add_test(NAME io_volume COMMAND sh -c "rm -rf '${scratch}' && mkdir -p '${scratch}' && exec \"$0\" \"$@\""
    $<TARGET_FILE:io_volume> ${scratch} "${SAMPLE_OIIOTOOL_ARG}" "${_texsample}")
  set_tests_properties(io_volume PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 60
    ENVIRONMENT "OCIO=;${SAMPLE_IO_SAN_ENV}")
endif()
