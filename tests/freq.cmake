# Frequency-test harness (tools/freq): tests/freq_*.c link the texsample_freq
# library; freq_cli runs `texsample freq --quick` end to end.
if(TARGET texsample_freq)
  file(GLOB FREQ_TESTS CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/freq_*.c)
  list(FILTER FREQ_TESTS EXCLUDE REGEX "/freq_cli\\.c$")
  foreach(src ${FREQ_TESTS})
    get_filename_component(name ${src} NAME_WE)
    add_executable(${name} ${src})
    target_link_libraries(${name} PRIVATE texsample_freq)
    target_include_directories(${name} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
    target_compile_options(${name} PRIVATE ${SAMPLE_WARNINGS})
    add_test(NAME ${name} COMMAND ${name})
    set_tests_properties(${name} PROPERTIES TIMEOUT 300)
  endforeach()
  if(TARGET texsample AND EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/freq_cli.c)
    add_executable(freq_cli ${CMAKE_CURRENT_SOURCE_DIR}/freq_cli.c)
    target_link_libraries(freq_cli PRIVATE texsample_freq)
    target_include_directories(freq_cli PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
    target_compile_options(freq_cli PRIVATE ${SAMPLE_WARNINGS})
    add_test(NAME freq_cli COMMAND freq_cli $<TARGET_FILE:texsample> ${CMAKE_CURRENT_BINARY_DIR}/freq_cli_out)
    set_tests_properties(freq_cli PROPERTIES TIMEOUT 300)
    # The page in headless Chromium (tests/html_check.sh); skipped without it.
    add_test(NAME freq_html COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/freq_html.sh
             $<TARGET_FILE:texsample> ${CMAKE_CURRENT_BINARY_DIR}/freq_html.out)
    set_tests_properties(freq_html PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300
      ENVIRONMENT "ASAN_OPTIONS=new_delete_type_mismatch=0")
  endif()
endif()
