# texsample compare (tools/compare/): a static library shared by the
# texsample executable and the tests (tests/compare.cmake), so that its
# sources compile once per build. cmd_compare.c is the subcommand and stays
# in texsample; sample_compare.c is the Python API's and builds into
# libsample_measure only (tools/sample_measure.cmake). The command-line
# helpers (cli.c, whose file writer the report uses) ride in the library.
file(GLOB TEXSAMPLE_COMPARE_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/compare/*.c)
list(FILTER TEXSAMPLE_COMPARE_SOURCES EXCLUDE REGEX "/(cmd_compare|sample_compare)\\.c$")
list(APPEND TEXSAMPLE_COMPARE_SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/cli.c)
add_library(texsample_compare STATIC ${TEXSAMPLE_COMPARE_SOURCES})
target_include_directories(texsample_compare PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/compare ${CMAKE_CURRENT_SOURCE_DIR})
target_compile_options(texsample_compare PRIVATE ${SAMPLE_WARNINGS})
target_link_libraries(texsample_compare PUBLIC texsample_freq texsample_render m)
# Its own scenes read the photograph from testimages/ of this source tree,
# as the renderer's built-in scenes do (tools/render.cmake).
set_property(SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/compare/scenes.c APPEND PROPERTY
  COMPILE_DEFINITIONS TEXSAMPLE_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
# texsample globbed tools/*.c and tools/*/*.c already; drop the library's
# sources from it.
get_target_property(_ts_sources texsample SOURCES)
list(REMOVE_ITEM _ts_sources ${TEXSAMPLE_COMPARE_SOURCES})
set_property(TARGET texsample PROPERTY SOURCES ${_ts_sources})
target_link_libraries(texsample PRIVATE texsample_compare)
