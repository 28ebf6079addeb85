# Independent implementations in tests/oracles/ that the suite checks
# libsample against. lean_footprint.c is a lean Blinn–Newell and EWA,
# written apart from libsample's footprint_*.c for the bench's case (float
# RGBA, REPEAT, no biases): on bench's query sets over a small texture,
# where many footprints wrap, its results must be libsample's to 1e-5. Its
# timings are printed, never judged. It links the bench's sources without
# OpenImageIO (tools/bench/bench_no_oiio.h) and shares the developer's
# probe helpers (dev/probe_util.h).
add_executable(lean_footprint ${CMAKE_CURRENT_SOURCE_DIR}/oracles/lean_footprint.c
                              ${PROJECT_SOURCE_DIR}/tools/bench/queries.c ${PROJECT_SOURCE_DIR}/tools/bench/engines.c)
target_include_directories(lean_footprint PRIVATE ${PROJECT_SOURCE_DIR}/libsample/src ${PROJECT_SOURCE_DIR}/tools/bench
                                                  ${PROJECT_SOURCE_DIR}/tools/oiio ${PROJECT_SOURCE_DIR}/dev)
# texsample_freq: the filter registry and libsample's backend (tools/backend.h).
target_link_libraries(lean_footprint PRIVATE texsample_freq sample m)
target_compile_options(lean_footprint PRIVATE ${SAMPLE_WARNINGS})
foreach(case "blinn-newell;minify" "blinn-newell;aniso8" "ewa;minify" "ewa;aniso8")
  list(GET case 0 filt)
  list(GET case 1 set)
  add_test(NAME lean_footprint_${filt}_${set} COMMAND lean_footprint ${filt} ${set} 4096 1)
  set_tests_properties(lean_footprint_${filt}_${set} PROPERTIES ENVIRONMENT PB_SIZE=64 TIMEOUT 120)
endforeach()
