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
