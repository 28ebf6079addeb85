# OpenImageIO's TextureSystem behind a C API (tools/oiio/oiio_ts.h): a static
# library shared by texsample (bench, compare, freq) and the tests
# (tests/oiio.cmake). Debian 12 ships a CMake package; pkg-config otherwise.
find_package(OpenImageIO CONFIG QUIET)
if(TARGET OpenImageIO::OpenImageIO)
  set(_oiio_lib OpenImageIO::OpenImageIO)
  # Debian 12's package names /usr/include/opencv4 in its interface even
  # when OpenCV's headers are not installed, which CMake treats as an error;
  # keep only the directories that exist.
  get_target_property(_oiio_inc OpenImageIO::OpenImageIO INTERFACE_INCLUDE_DIRECTORIES)
  set(_oiio_inc_ok)
  foreach(d ${_oiio_inc})
    if(EXISTS "${d}")
      list(APPEND _oiio_inc_ok "${d}")
    endif()
  endforeach()
  set_target_properties(OpenImageIO::OpenImageIO PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_oiio_inc_ok}")
else()
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(OIIO_PC REQUIRED IMPORTED_TARGET OpenImageIO)
  set(_oiio_lib PkgConfig::OIIO_PC)
endif()
file(GLOB TEXSAMPLE_OIIO_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/oiio/*.cpp)
add_library(texsample_oiio STATIC ${TEXSAMPLE_OIIO_SOURCES})
target_include_directories(texsample_oiio PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/oiio)
target_compile_options(texsample_oiio PRIVATE -Wall -Wextra -Wpedantic -Wshadow)
target_link_libraries(texsample_oiio PUBLIC sample ${_oiio_lib})
# texsample globbed tools/*/*.cpp already; the library owns these.
get_target_property(_ts_sources texsample SOURCES)
list(REMOVE_ITEM _ts_sources ${TEXSAMPLE_OIIO_SOURCES})
set_property(TARGET texsample PROPERTY SOURCES ${_ts_sources})
target_link_libraries(texsample PRIVATE texsample_oiio)
target_compile_definitions(texsample PRIVATE TEXSAMPLE_HAVE_OIIO=1)
