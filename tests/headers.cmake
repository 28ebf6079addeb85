# Every internal header of libsample stands alone: each is compiled as the
# only include of a translation unit of its own, so a header that leans on
# what another happened to include before it fails the build.
file(GLOB _sample_headers CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/libsample/src/*.h)
set(_sample_header_tus "")
foreach(h ${_sample_headers})
  get_filename_component(_name ${h} NAME_WE)
  set(_tu ${CMAKE_CURRENT_BINARY_DIR}/headers/${_name}_alone.c)
  file(CONFIGURE OUTPUT ${_tu} CONTENT "#include \"${_name}.h\"\nint sample_header_${_name}_alone;\n")
  list(APPEND _sample_header_tus ${_tu})
endforeach()
add_library(headers_alone OBJECT ${_sample_header_tus})
target_include_directories(headers_alone PRIVATE ${PROJECT_SOURCE_DIR}/libsample/src ${PROJECT_SOURCE_DIR}/libsample/include)
target_compile_options(headers_alone PRIVATE ${SAMPLE_WARNINGS})
