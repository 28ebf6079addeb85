# libsample_io tests (doc/io-and-colour.md, "Tests"). Each program gets the
# testimages folder and a scratch folder of its own in the build tree.
if(TARGET sample_io)
  # Suppressions match only full stacks; the leaking frames are in libraries
  # built without frame pointers, so the slow unwinder is needed to see them.
  set(SAMPLE_IO_SAN_ENV "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_SOURCE_DIR}/io_lsan.supp;ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:fast_unwind_on_malloc=0")
  # The command-line tools some tests compare with: passed as an empty
  # argument where missing, and those tests then exit 77 (ctest: Skipped)
  # after checking everything else (doc/testing.md, "Skipped, not passed").
  foreach(tool maketx oiiotool exrheader exrenvmap)
    string(TOUPPER ${tool} TOOL)
    find_program(SAMPLE_${TOOL} ${tool})
    if(SAMPLE_${TOOL})
      set(SAMPLE_${TOOL}_ARG "${SAMPLE_${TOOL}}")
    else()
      set(SAMPLE_${TOOL}_ARG "")
    endif()
  endforeach()
  foreach(name io_read io_colour io_mip io_bad io_hostile io_make_mip)
    add_executable(${name} ${CMAKE_CURRENT_SOURCE_DIR}/${name}.c)
    target_link_libraries(${name} PRIVATE sample_io sample m)
    target_include_directories(${name} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR} ${PROJECT_SOURCE_DIR}/libsample/io/src)
    target_compile_options(${name} PRIVATE ${SAMPLE_WARNINGS})
    set(scratch ${CMAKE_CURRENT_BINARY_DIR}/${name}_scratch)
    add_test(NAME ${name} COMMAND sh -c "rm -rf '${scratch}' && mkdir -p '${scratch}' && exec \"$0\" \"$@\""
      $<TARGET_FILE:${name}> ${PROJECT_SOURCE_DIR}/testimages ${scratch}
      "${SAMPLE_MAKETX_ARG}" "${SAMPLE_OIIOTOOL_ARG}")
    # The shipped config, whatever $OCIO the developer has set; OIIO's own
    # leaks suppressed (tests/io_lsan.supp says which and why).
    set_tests_properties(${name} PROPERTIES TIMEOUT 300
      ENVIRONMENT "OCIO=;${SAMPLE_IO_SAN_ENV}")
  endforeach()
  # io_mip compares with maketx's pyramids through oiiotool.
  set_tests_properties(io_mip io_make_mip PROPERTIES SKIP_RETURN_CODE 77)
  # Environment maps: maketx --envlatl output, OpenImageIO's reading of the
  # attributes, OpenEXR's exrenvmap as the judge of the cube layout.
  add_executable(io_env ${CMAKE_CURRENT_SOURCE_DIR}/io_env.c)
  target_link_libraries(io_env PRIVATE sample_io sample m)
  target_include_directories(io_env PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_options(io_env PRIVATE ${SAMPLE_WARNINGS})
  set(scratch ${CMAKE_CURRENT_BINARY_DIR}/io_env_scratch)
  add_test(NAME io_env COMMAND sh -c "rm -rf '${scratch}' && mkdir -p '${scratch}' && exec \"$0\" \"$@\""
    $<TARGET_FILE:io_env> ${PROJECT_SOURCE_DIR}/testimages ${scratch}
    "${SAMPLE_MAKETX_ARG}" "${SAMPLE_OIIOTOOL_ARG}" "${SAMPLE_EXRENVMAP_ARG}")
  set_tests_properties(io_env PROPERTIES TIMEOUT 120 SKIP_RETURN_CODE 77 ENVIRONMENT "OCIO=;${SAMPLE_IO_SAN_ENV}")
  # Interrupted writes, through the library and through texsample mip
  # (an empty argument where texsample is not built: that part skipped).
  add_executable(io_signal ${CMAKE_CURRENT_SOURCE_DIR}/io_signal.c)
  target_link_libraries(io_signal PRIVATE sample_io sample m)
  target_include_directories(io_signal PRIVATE ${CMAKE_CURRENT_SOURCE_DIR} ${PROJECT_SOURCE_DIR}/libsample/io/src)
  target_compile_options(io_signal PRIVATE ${SAMPLE_WARNINGS})
  set(scratch ${CMAKE_CURRENT_BINARY_DIR}/io_signal_scratch)
  add_test(NAME io_signal COMMAND sh -c "rm -rf '${scratch}' && mkdir -p '${scratch}' && exec \"$0\" \"$@\""
    $<TARGET_FILE:io_signal> ${PROJECT_SOURCE_DIR}/testimages ${scratch} "$<$<TARGET_EXISTS:texsample>:$<TARGET_FILE:texsample>>")
  set_tests_properties(io_signal PROPERTIES TIMEOUT 120 SKIP_RETURN_CODE 77 ENVIRONMENT "OCIO=;${SAMPLE_IO_SAN_ENV}")
  if(TARGET texsample)
    add_test(NAME io_cli COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/io_cli.sh $<TARGET_FILE:texsample>
      ${PROJECT_SOURCE_DIR}/testimages ${CMAKE_CURRENT_BINARY_DIR}/io_cli_scratch
      "${SAMPLE_OIIOTOOL_ARG}" "${SAMPLE_EXRHEADER_ARG}")
    set_tests_properties(io_cli PROPERTIES TIMEOUT 300 ENVIRONMENT "OCIO=" SKIP_RETURN_CODE 77)
    # Hostile files through the program: a huge-claiming TIFF under a 1 GiB
    # address-space limit, /dev/zero, a FIFO, a directory.
    add_test(NAME io_hostile_cli COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/io_hostile_cli.sh $<TARGET_FILE:texsample>
      ${CMAKE_CURRENT_BINARY_DIR}/io_hostile_cli_scratch)
    set_tests_properties(io_hostile_cli PROPERTIES TIMEOUT 120 ENVIRONMENT "OCIO=" SKIP_RETURN_CODE 77)
  endif()
  if(COMMAND sample_add_fuzzer)
    sample_add_fuzzer(fuzz_io fuzz_io.c corpus_io sample_io sample)
    if(TARGET fuzz_io)
      set_tests_properties(fuzz_io PROPERTIES
        ENVIRONMENT "OCIO=;${SAMPLE_IO_SAN_ENV}")
    endif()
  endif()
endif()
