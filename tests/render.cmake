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
    # render_cache converts testimages/photo.jpg.
    target_compile_definitions(${name} PRIVATE TEXSAMPLE_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
    # The texsample program for the tests that run the command line.
    add_test(NAME ${name} COMMAND ${name} $<TARGET_FILE:texsample>)
    set_tests_properties(${name} PROPERTIES TIMEOUT 300 SKIP_RETURN_CODE 77)
  endforeach()
  # render_image writes its grey and grey + alpha PNGs with zlib (a
  # dependency of libpng and OpenEXR, so present wherever libsample_io is).
  find_package(ZLIB)
  if(TARGET render_image AND ZLIB_FOUND)
    target_link_libraries(render_image PRIVATE ZLIB::ZLIB)
    target_compile_definitions(render_image PRIVATE RENDER_TEST_HAVE_ZLIB=1)
  endif()
endif()
