# texsample's command line, end to end. The command-line tests run the
# front program (texsample_cli, tools/CMakeLists.txt), which runs the image
# program (texsample) for image files.
if(TARGET texsample_cli)
  add_executable(cli_lookup ${CMAKE_CURRENT_SOURCE_DIR}/cli_lookup.c)
  target_link_libraries(cli_lookup PRIVATE sample)
  target_include_directories(cli_lookup PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  add_test(NAME cli_lookup COMMAND cli_lookup $<TARGET_FILE:texsample_cli> ${PROJECT_SOURCE_DIR})
  # Start-up without OpenImageIO's libraries (LD_DEBUG=files); 77 without
  # the loader's account.
  add_executable(cli_startup ${CMAKE_CURRENT_SOURCE_DIR}/cli_startup.c)
  target_include_directories(cli_startup PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_options(cli_startup PRIVATE ${SAMPLE_WARNINGS})
  add_test(NAME cli_startup COMMAND cli_startup $<TARGET_FILE:texsample_cli>
           ${PROJECT_SOURCE_DIR}/testimages/rgb8.png)
  set_tests_properties(cli_startup PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 60)
  # Every option a command asks about is in its --help.
  add_executable(cli_options ${CMAKE_CURRENT_SOURCE_DIR}/cli_options.c)
  target_include_directories(cli_options PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_options(cli_options PRIVATE ${SAMPLE_WARNINGS})
  add_test(NAME cli_options COMMAND cli_options $<TARGET_FILE:texsample_cli>)
  set_tests_properties(cli_options PROPERTIES TIMEOUT 60)
  # Colour labels, colour-space names and stored wrap modes (the flat file
  # with wrap modes is made by oiiotool: that part skipped, 77, without it).
  add_executable(cli_colour ${CMAKE_CURRENT_SOURCE_DIR}/cli_colour.c)
  target_include_directories(cli_colour PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_options(cli_colour PRIVATE ${SAMPLE_WARNINGS})
  add_test(NAME cli_colour COMMAND cli_colour $<TARGET_FILE:texsample_cli> ${PROJECT_SOURCE_DIR})
  set_tests_properties(cli_colour PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 60)
endif()
# The filter registry (tools/filters.h) the tools share: its names, aliases
# and settings, and that each tool's --help lists and runs its names.
if(TARGET texsample AND TARGET texsample_freq)
  add_executable(filter_registry ${CMAKE_CURRENT_SOURCE_DIR}/filter_registry.c)
  target_link_libraries(filter_registry PRIVATE texsample_freq)
  target_include_directories(filter_registry PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_options(filter_registry PRIVATE ${SAMPLE_WARNINGS})
  add_test(NAME filter_registry COMMAND filter_registry $<TARGET_FILE:texsample_cli>
           ${CMAKE_CURRENT_BINARY_DIR}/filter_registry_out)
  # See tests/oiio.cmake: OIIO 2.4's TextureSystem::destroy under ASan.
  set_tests_properties(filter_registry PROPERTIES TIMEOUT 300
    ENVIRONMENT "ASAN_OPTIONS=new_delete_type_mismatch=0")
endif()
