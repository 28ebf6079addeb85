# The OpenImageIO TextureSystem shim (tools/oiio) checked against libsample.
if(TARGET texsample_oiio)
  # With OpenImageIO's backend (tools/backend.h; the interface rides in
  # texsample_freq).
  add_executable(oiio_shim ${CMAKE_CURRENT_SOURCE_DIR}/oiio_shim.c ${PROJECT_SOURCE_DIR}/tools/backends/oiio.c)
  target_link_libraries(oiio_shim PRIVATE texsample_oiio texsample_freq sample)
  target_include_directories(oiio_shim PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_definitions(oiio_shim PRIVATE TEXSAMPLE_HAVE_OIIO=1)
  target_compile_options(oiio_shim PRIVATE ${SAMPLE_WARNINGS})
  # C++ runtime for the static library's OpenImageIO calls.
  set_target_properties(oiio_shim PROPERTIES LINKER_LANGUAGE CXX)
  add_test(NAME oiio_shim COMMAND oiio_shim)
  # OpenImageIO 2.4's TextureSystem::destroy() deletes its implementation
  # through the base-class pointer with a sized delete, which ASan reports as
  # new-delete-type-mismatch inside libOpenImageIO (not in our code).
  set_tests_properties(oiio_shim PROPERTIES TIMEOUT 120
    ENVIRONMENT "ASAN_OPTIONS=new_delete_type_mismatch=0")
endif()
