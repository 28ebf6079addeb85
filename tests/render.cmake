# Renderer tests: tests/render_*.c, each linked to the texsample_render
# library that tools/render.cmake defines (with its internal headers).
if(TARGET texsample_render)
  file(GLOB RENDER_TESTS CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/render_*.c)
  foreach(src ${RENDER_TESTS})
    get_filename_component(name ${src} NAME_WE)
    add_executable(${name} ${src})
    target_link_libraries(${name} PRIVATE texsample_render)
    target_include_directories(${name} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
    target_compile_options(${name} PRIVATE ${SAMPLE_WARNINGS})
    add_test(NAME ${name} COMMAND ${name})
    set_tests_properties(${name} PROPERTIES TIMEOUT 300)
  endforeach()
endif()
