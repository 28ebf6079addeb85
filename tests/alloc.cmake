# Allocation failure injection through the linker's --wrap (GNU ld / lld).
# (Under ASan the wrapped calls reach ASan's allocator, and LeakSanitizer
# checks nothing was left behind.)
if(NOT SAMPLE_TSAN AND CMAKE_C_COMPILER_ID MATCHES "GNU|Clang")
  add_executable(alloc_failure ${CMAKE_CURRENT_SOURCE_DIR}/alloc_failure.c)
  target_link_libraries(alloc_failure PRIVATE sample)
  target_include_directories(alloc_failure PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_link_options(alloc_failure PRIVATE -Wl,--wrap=malloc,--wrap=calloc,--wrap=free)
  add_test(NAME alloc_failure COMMAND alloc_failure)
endif()
