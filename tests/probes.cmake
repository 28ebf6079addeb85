# The developer's probes in scripts/ (doc/performance-passes.md,
# doc/performance-passes-2.md), built here so that they keep compiling
# against the library they measure, and the bench's timer on its own
# (bench_timer.c). All link the bench's sources without OpenImageIO
# (tools/bench/bench_no_oiio.h). lean_footprint is also a test: its
# lean Blinn–Newell and EWA, written apart from libsample's, must give
# libsample's results to 1e-5 on bench's query sets (small textures,
# where many footprints wrap). Its timings are printed, never judged.
foreach(probe perf_probe lean_footprint)
  add_executable(${probe} ${PROJECT_SOURCE_DIR}/scripts/${probe}.c ${PROJECT_SOURCE_DIR}/tools/bench/queries.c
                          ${PROJECT_SOURCE_DIR}/tools/bench/engines.c ${PROJECT_SOURCE_DIR}/tools/filters.c)
  target_include_directories(${probe} PRIVATE ${PROJECT_SOURCE_DIR}/libsample/src ${PROJECT_SOURCE_DIR}/tools/bench
                                              ${PROJECT_SOURCE_DIR}/tools/oiio ${PROJECT_SOURCE_DIR}/scripts)
  target_link_libraries(${probe} PRIVATE sample m)
  target_compile_options(${probe} PRIVATE ${SAMPLE_WARNINGS})
endforeach()
find_package(Threads REQUIRED)
add_executable(bench_timer ${CMAKE_CURRENT_SOURCE_DIR}/bench_timer.c ${PROJECT_SOURCE_DIR}/tools/bench/timing.c
                           ${PROJECT_SOURCE_DIR}/tools/bench/queries.c ${PROJECT_SOURCE_DIR}/tools/bench/engines.c
                           ${PROJECT_SOURCE_DIR}/tools/filters.c)
target_include_directories(bench_timer PRIVATE ${CMAKE_CURRENT_SOURCE_DIR} ${PROJECT_SOURCE_DIR}/tools/bench
                                               ${PROJECT_SOURCE_DIR}/tools/oiio)
target_link_libraries(bench_timer PRIVATE sample Threads::Threads m)
target_compile_options(bench_timer PRIVATE ${SAMPLE_WARNINGS})
add_test(NAME bench_timer COMMAND bench_timer)
set_tests_properties(bench_timer PROPERTIES TIMEOUT 120)
foreach(case "blinn-newell;minify" "blinn-newell;aniso8" "ewa;minify" "ewa;aniso8")
  list(GET case 0 filt)
  list(GET case 1 set)
  add_test(NAME lean_footprint_${filt}_${set} COMMAND lean_footprint ${filt} ${set} 4096 1)
  set_tests_properties(lean_footprint_${filt}_${set} PROPERTIES ENVIRONMENT PB_SIZE=64 TIMEOUT 120)
endforeach()
