# texsample's command line, end to end.
if(TARGET texsample)
  add_executable(cli_lookup ${CMAKE_CURRENT_SOURCE_DIR}/cli_lookup.c)
  target_link_libraries(cli_lookup PRIVATE sample)
  target_include_directories(cli_lookup PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  add_test(NAME cli_lookup COMMAND cli_lookup $<TARGET_FILE:texsample>)
endif()
# The filter registry (tools/filters.h) the tools share: its names, aliases
# and settings, and that each tool's --help lists and runs its names.
if(TARGET texsample AND TARGET texsample_freq)
  add_executable(filter_registry ${CMAKE_CURRENT_SOURCE_DIR}/filter_registry.c)
  target_link_libraries(filter_registry PRIVATE texsample_freq)
  target_include_directories(filter_registry PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_options(filter_registry PRIVATE ${SAMPLE_WARNINGS})
  add_test(NAME filter_registry COMMAND filter_registry $<TARGET_FILE:texsample>
           ${CMAKE_CURRENT_BINARY_DIR}/filter_registry_out)
  # See tests/oiio.cmake: OIIO 2.4's TextureSystem::destroy under ASan.
  set_tests_properties(filter_registry PROPERTIES TIMEOUT 300
    ENVIRONMENT "ASAN_OPTIONS=new_delete_type_mismatch=0")
endif()
