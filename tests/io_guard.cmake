# Header pre-flights: OpenEXR attribute sizes, JPEG APP13 blocks
# (doc/io-and-colour.md, doc/guarantees.md).
if(TARGET sample_io)
  foreach(t io_exr_guard io_jpeg_guard)
    add_executable(${t} ${CMAKE_CURRENT_SOURCE_DIR}/${t}.c)
    target_link_libraries(${t} PRIVATE sample_io sample)
    target_include_directories(${t} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
    target_compile_definitions(${t} PRIVATE SOURCE_DIR="${PROJECT_SOURCE_DIR}")
    set_target_properties(${t} PROPERTIES LINKER_LANGUAGE CXX)
    add_test(NAME ${t} COMMAND ${t})
  endforeach()
endif()
