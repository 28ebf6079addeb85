# The reference renderer (tools/render/): a static library shared by the
# texsample executable and the tests (tests/render.cmake). cmd_render.c is
# the subcommand and stays in texsample; the rest moves out of its glob.
file(GLOB TEXSAMPLE_RENDER_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/render/*.c)
list(FILTER TEXSAMPLE_RENDER_SOURCES EXCLUDE REGEX "/cmd_render\\.c$")
add_library(texsample_render STATIC ${TEXSAMPLE_RENDER_SOURCES})
target_include_directories(texsample_render PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/render)
target_compile_options(texsample_render PRIVATE ${SAMPLE_WARNINGS})
target_link_libraries(texsample_render PUBLIC sample Threads::Threads m)
# The built-in image scenes read testimages/ of this source tree.
target_compile_definitions(texsample_render PRIVATE TEXSAMPLE_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
# Image textures (imagetex.c) need libsample_io; without it they are refused.
if(TARGET sample_io)
  target_link_libraries(texsample_render PUBLIC sample_io)
  # PUBLIC: the renderer tests check the I/O only where it exists.
  target_compile_definitions(texsample_render PUBLIC TEXSAMPLE_HAVE_IO=1)
endif()
# texsample globbed tools/*/*.c already; drop the library's sources from it.
get_target_property(_ts_sources texsample SOURCES)
list(REMOVE_ITEM _ts_sources ${TEXSAMPLE_RENDER_SOURCES})
set_property(TARGET texsample PROPERTY SOURCES ${_ts_sources})
target_link_libraries(texsample PRIVATE texsample_render)
