# libFuzzer targets (configure with CC=clang CXX=clang++ -DSAMPLE_FUZZ=ON).
# sample_add_fuzzer(NAME SOURCE CORPUS_DIR [LIBS...]) builds tests/fuzz/SOURCE
# and registers a bounded ctest run (label "fuzz") that starts from the
# committed corpus and writes new inputs only into the build tree.
# Longer runs, and merging what they find into the committed corpus
# (-merge=1): doc/testing.md, "Longer fuzzing".
set(SAMPLE_FUZZ_SECONDS 20 CACHE STRING "Seconds each fuzzer runs in ctest")
if(SAMPLE_FUZZ AND NOT TARGET fuzzers)
  add_custom_target(fuzzers) # `cmake --build B --target fuzzers` builds them all
endif()
function(sample_add_fuzzer name source corpus)
  if(NOT SAMPLE_FUZZ)
    return()
  endif()
  add_executable(${name} ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/${source})
  add_dependencies(fuzzers ${name})
  # Compiled like everything else in this build (top CMakeLists.txt); only
  # the fuzzers link libFuzzer and its main().
  target_link_options(${name} PRIVATE -fsanitize=fuzzer)
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/libsample/src ${CMAKE_CURRENT_SOURCE_DIR})
  target_link_libraries(${name} PRIVATE ${ARGN})
  set(work ${CMAKE_CURRENT_BINARY_DIR}/fuzz_${name})
  add_test(NAME ${name}
    COMMAND sh -c "mkdir -p '${work}' && exec '$<TARGET_FILE:${name}>' -max_total_time=${SAMPLE_FUZZ_SECONDS} -timeout=10 -rss_limit_mb=2048 -artifact_prefix='${work}/' '${work}' '${CMAKE_CURRENT_SOURCE_DIR}/fuzz/${corpus}'")
  set_tests_properties(${name} PROPERTIES LABELS fuzz TIMEOUT 600)
endfunction()

sample_add_fuzzer(fuzz_sample fuzz_sample.c corpus_sample sample)

# fuzz_flags: every compile command of this build, and at least one of each
# library target outside tests/ (libsample's static and shared libraries,
# each instruction set's fast-path objects, libsample_io, the tools'
# libraries), carries the fuzzing build's instrumentation.
if(SAMPLE_FUZZ)
  set(_fuzz_libs "")
  set(_fuzz_dirs ${PROJECT_SOURCE_DIR})
  while(_fuzz_dirs)
    list(POP_FRONT _fuzz_dirs _dir)
    get_property(_sub DIRECTORY ${_dir} PROPERTY SUBDIRECTORIES)
    list(REMOVE_ITEM _sub ${CMAKE_CURRENT_SOURCE_DIR})
    list(APPEND _fuzz_dirs ${_sub})
    get_property(_targets DIRECTORY ${_dir} PROPERTY BUILDSYSTEM_TARGETS)
    foreach(_t ${_targets})
      get_target_property(_type ${_t} TYPE)
      if(_type MATCHES "^(STATIC|SHARED|MODULE|OBJECT)_LIBRARY$")
        list(APPEND _fuzz_libs ${_t})
      endif()
    endforeach()
  endwhile()
  add_test(NAME fuzz_flags COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/fuzz_flags.sh
    ${PROJECT_BINARY_DIR}/compile_commands.json ${_fuzz_libs})
  set_tests_properties(fuzz_flags PROPERTIES LABELS fuzz TIMEOUT 30)
endif()
