# texsample bench --save, replayed by tools/bench/oiio_replay: the saved
# files and manifest are checked, and the replay's OIIO lookups must equal
# the shim's for the same queries (values only; speeds are never asserted).
if(TARGET texsample AND TARGET oiio_replay AND TARGET texsample_oiio)
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(REPLAY_CJSON REQUIRED IMPORTED_TARGET libcjson)
  # queries.c: the test regenerates bench's query sets to compare the files
  # with them bit for bit.
  add_executable(bench_replay ${CMAKE_CURRENT_SOURCE_DIR}/bench_replay.c
                 ${PROJECT_SOURCE_DIR}/tools/bench/queries.c)
  target_include_directories(bench_replay PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}
                             ${PROJECT_SOURCE_DIR}/tools/bench)
  target_link_libraries(bench_replay PRIVATE texsample_oiio sample PkgConfig::REPLAY_CJSON m)
  target_compile_options(bench_replay PRIVATE ${SAMPLE_WARNINGS})
  # C++ runtime for the static library's OpenImageIO calls.
  set_target_properties(bench_replay PROPERTIES LINKER_LANGUAGE CXX)
  add_test(NAME bench_replay COMMAND bench_replay $<TARGET_FILE:texsample>
           $<TARGET_FILE:oiio_replay> ${CMAKE_CURRENT_BINARY_DIR}/bench_replay.out)
  # See tests/oiio.cmake: OIIO 2.4's TextureSystem::destroy under ASan
  # (oiio_replay and texsample, run by the test, inherit it).
  set_tests_properties(bench_replay PROPERTIES TIMEOUT 120
    ENVIRONMENT "ASAN_OPTIONS=new_delete_type_mismatch=0")
endif()
