# The developer's timing probe in dev/ (perf_probe.c, run by
# dev/perf_probe.sh), built here so that it keeps compiling against the
# library it measures, and the bench's timer on its own (bench_timer.c).
# Both link the bench's sources without OpenImageIO
# (tools/bench/bench_no_oiio.h). The lean footprint oracle, which shares
# dev/probe_util.h, is a test of its own: tests/oracles.cmake.
add_executable(perf_probe ${PROJECT_SOURCE_DIR}/dev/perf_probe.c ${PROJECT_SOURCE_DIR}/tools/bench/queries.c
                          ${PROJECT_SOURCE_DIR}/tools/bench/engines.c)
target_include_directories(perf_probe PRIVATE ${PROJECT_SOURCE_DIR}/libsample/src ${PROJECT_SOURCE_DIR}/tools/bench
                                              ${PROJECT_SOURCE_DIR}/tools/oiio ${PROJECT_SOURCE_DIR}/dev)
# texsample_freq: the filter registry and libsample's backend (tools/backend.h).
target_link_libraries(perf_probe PRIVATE texsample_freq sample m)
target_compile_options(perf_probe PRIVATE ${SAMPLE_WARNINGS})
find_package(Threads REQUIRED)
add_executable(bench_timer ${CMAKE_CURRENT_SOURCE_DIR}/bench_timer.c ${PROJECT_SOURCE_DIR}/tools/bench/timing.c
                           ${PROJECT_SOURCE_DIR}/tools/bench/queries.c ${PROJECT_SOURCE_DIR}/tools/bench/engines.c)
target_include_directories(bench_timer PRIVATE ${CMAKE_CURRENT_SOURCE_DIR} ${PROJECT_SOURCE_DIR}/tools/bench
                                               ${PROJECT_SOURCE_DIR}/tools/oiio)
target_link_libraries(bench_timer PRIVATE texsample_freq sample Threads::Threads m)
target_compile_options(bench_timer PRIVATE ${SAMPLE_WARNINGS})
add_test(NAME bench_timer COMMAND bench_timer)
set_tests_properties(bench_timer PROPERTIES TIMEOUT 120)
