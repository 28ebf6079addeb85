# texsample bench: a smoke test only (help, usage errors, a tiny run whose
# JSON is parsed and checked for shape and for the exact texel counts).
# Speeds are never asserted.
if(TARGET texsample)
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(BENCH_CJSON REQUIRED IMPORTED_TARGET libcjson)
  add_executable(bench_cli ${CMAKE_CURRENT_SOURCE_DIR}/bench_cli.c)
  target_include_directories(bench_cli PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_link_libraries(bench_cli PRIVATE PkgConfig::BENCH_CJSON)
  target_compile_options(bench_cli PRIVATE ${SAMPLE_WARNINGS})
  add_test(NAME bench_cli COMMAND bench_cli $<TARGET_FILE:texsample>
           ${CMAKE_CURRENT_BINARY_DIR}/bench_cli.out)
  # See tests/oiio.cmake: OIIO 2.4's TextureSystem::destroy under ASan.
  set_tests_properties(bench_cli PROPERTIES TIMEOUT 300
    ENVIRONMENT "ASAN_OPTIONS=new_delete_type_mismatch=0")
endif()
