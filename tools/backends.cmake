# The backends (tools/backend.h) beside libsample's (which rides in
# texsample_freq with the interface, tools/freq.cmake): OpenGL through EGL
# and outside programs, a static library shared by texsample (compare,
# freq, bench) and the tests (tests/backends.cmake); OpenImageIO's
# (backends/oiio.c) is compiled into texsample, which has the OpenImageIO
# shim (tools/oiio.cmake). The OpenGL backend is compiled in where
# CMake finds EGL and the GL headers (Debian: libegl-dev, libgl-dev; at run
# time Mesa's EGL driver, libegl-mesa0); elsewhere it reports that it is
# missing and its tests skip.
set(TEXSAMPLE_BACKEND_SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/backends/gl.c
  ${CMAKE_CURRENT_SOURCE_DIR}/backends/program.c)
add_library(texsample_backends STATIC ${TEXSAMPLE_BACKEND_SOURCES})
target_include_directories(texsample_backends PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
target_compile_options(texsample_backends PRIVATE ${SAMPLE_WARNINGS})
# The registry (tools/filters.c) and the interface (tools/backend.c) ride in
# texsample_freq (tools/freq.cmake).
target_link_libraries(texsample_backends PUBLIC sample texsample_freq)
set(OpenGL_GL_PREFERENCE GLVND)
find_package(OpenGL QUIET COMPONENTS OpenGL EGL)
if(OpenGL_OpenGL_FOUND AND OpenGL_EGL_FOUND)
  target_link_libraries(texsample_backends PRIVATE OpenGL::OpenGL OpenGL::EGL)
  target_compile_definitions(texsample_backends PRIVATE TEXSAMPLE_HAVE_GL=1)
  set(TEXSAMPLE_HAVE_GL ON)
else()
  message(STATUS "EGL or OpenGL not found: the gl-* rows will report that they are missing")
  set(TEXSAMPLE_HAVE_GL OFF)
endif()
# texsample globbed tools/*.c and tools/*/*.c already; the library owns these.
get_target_property(_ts_sources texsample SOURCES)
list(REMOVE_ITEM _ts_sources ${TEXSAMPLE_BACKEND_SOURCES})
set_property(TARGET texsample PROPERTY SOURCES ${_ts_sources})
target_link_libraries(texsample PRIVATE texsample_backends)
