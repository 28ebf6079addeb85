# texsample's command line, end to end.
if(TARGET texsample)
  add_executable(cli_lookup ${CMAKE_CURRENT_SOURCE_DIR}/cli_lookup.c)
  target_link_libraries(cli_lookup PRIVATE sample)
  target_include_directories(cli_lookup PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  add_test(NAME cli_lookup COMMAND cli_lookup $<TARGET_FILE:texsample>)
endif()
