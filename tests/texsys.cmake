# The texture system (doc/texture-system.md): texsys_cache checks the
# cache against resident textures, its failures and UDIM sets;
# texsys_threads samples from several threads while the cache evicts (and
# runs under ThreadSanitizer in CI: .ci/run); texsys_kinds checks cube maps,
# volumes and per-open colour spaces against the whole-file readers, and
# runs `texsample bench --textures` (its last argument oiiotool, from
# io.cmake: the volume part is skipped without it).
if(TARGET sample_io)
  foreach(name texsys_cache texsys_threads texsys_kinds)
    add_executable(${name} ${CMAKE_CURRENT_SOURCE_DIR}/${name}.c)
    target_link_libraries(${name} PRIVATE sample_io sample m Threads::Threads)
    target_include_directories(${name} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR} ${PROJECT_SOURCE_DIR}/libsample/io/src
      ${PROJECT_SOURCE_DIR}/libsample/src)
    target_compile_options(${name} PRIVATE ${SAMPLE_WARNINGS})
    set(scratch ${CMAKE_CURRENT_BINARY_DIR}/${name}_scratch)
    # texsys_cache also runs `texsample lookup --cache-mb` (an empty
    # argument where texsample is not built: that part skipped).
    add_test(NAME ${name} COMMAND sh -c "rm -rf '${scratch}' && mkdir -p '${scratch}' && exec \"$0\" \"$@\""
      $<TARGET_FILE:${name}> ${PROJECT_SOURCE_DIR}/testimages ${scratch}
      "$<$<TARGET_EXISTS:texsample>:$<TARGET_FILE:texsample>>" "${SAMPLE_OIIOTOOL_ARG}")
    set_tests_properties(${name} PROPERTIES TIMEOUT 120 SKIP_RETURN_CODE 77 ENVIRONMENT "OCIO=;${SAMPLE_IO_SAN_ENV}")
  endforeach()
  # The bench it runs destroys an OpenImageIO TextureSystem, whose 2.4
  # destroy() deletes through the wrong type: what .ci/run's
  # new_delete_type_mismatch=0 allows every test, appended to the
  # ASAN_OPTIONS that SAMPLE_IO_SAN_ENV ends with.
  set_tests_properties(texsys_kinds PROPERTIES ENVIRONMENT "OCIO=;${SAMPLE_IO_SAN_ENV}:new_delete_type_mismatch=0")
endif()
