# OpenEXR header pre-flight (doc/io-and-colour.md, doc/guarantees.md).
if(TARGET sample_io)
  add_executable(io_exr_guard ${CMAKE_CURRENT_SOURCE_DIR}/io_exr_guard.c)
  target_link_libraries(io_exr_guard PRIVATE sample_io sample)
  target_include_directories(io_exr_guard PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_definitions(io_exr_guard PRIVATE SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  set_target_properties(io_exr_guard PROPERTIES LINKER_LANGUAGE CXX)
  add_test(NAME io_exr_guard COMMAND io_exr_guard)
endif()
