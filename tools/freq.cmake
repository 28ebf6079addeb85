# The frequency-test harness (tools/freq/): a static library shared by the
# texsample executable and the tests (tests/freq.cmake). The command line
# and file output stay in texsample, which has the CLI helpers; so do the
# backends that need OpenImageIO or EGL (tools/backends.cmake).
file(GLOB TEXSAMPLE_FREQ_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/freq/*.c)
list(FILTER TEXSAMPLE_FREQ_SOURCES EXCLUDE REGEX "/(cmd_freq|out)\\.c$")
# The filter registry (filters.h) that freq's rows and the other tools
# select from, and the backend interface with libsample's backend
# (backend.h), ride in the same library, so the tests see them too.
list(APPEND TEXSAMPLE_FREQ_SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/filters.c
  ${CMAKE_CURRENT_SOURCE_DIR}/backend.c ${CMAKE_CURRENT_SOURCE_DIR}/backends/libsample.c)
add_library(texsample_freq STATIC ${TEXSAMPLE_FREQ_SOURCES})
target_include_directories(texsample_freq PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/freq ${CMAKE_CURRENT_SOURCE_DIR})
target_compile_options(texsample_freq PRIVATE ${SAMPLE_WARNINGS})
target_link_libraries(texsample_freq PUBLIC sample m)
# texsample globbed tools/*/*.c already; drop the library's sources from it.
get_target_property(_ts_sources texsample SOURCES)
list(REMOVE_ITEM _ts_sources ${TEXSAMPLE_FREQ_SOURCES})
set_property(TARGET texsample PROPERTY SOURCES ${_ts_sources})
target_link_libraries(texsample PRIVATE texsample_freq)
