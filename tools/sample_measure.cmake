# libsample_measure: the tools' measurements as a shared library with a C
# API (tools/freq/sample_measure.h) for the Python package (doc/python.md):
# texsample freq's sweep (the sources of texsample_freq, tools/freq.cmake)
# and texsample compare's view, ground truth and metrics (tools/compare/)
# over the reference renderer's scenes (texsample_render,
# tools/render.cmake; this file is read after it). Only the two API files
# compile here: the freq, compare and renderer archives are linked as
# files, their objects made position-independent, so that their usage
# requirements (the static libsample) stay out: the library links
# the shared libsample (and libsample_io), a process holds one libsample,
# and the textures a callback is handed are that library's. Only
# sample_freq_* and sample_compare_* are exported.
# Not in the sanitizer and fuzzing builds: nothing there loads it (the
# Python tests are not run under them, tests/python.cmake).
if(TARGET texsample_render AND NOT SAMPLE_SANITIZE AND NOT SAMPLE_TSAN AND NOT SAMPLE_FUZZ)
  add_library(sample_measure SHARED ${CMAKE_CURRENT_SOURCE_DIR}/freq/sample_measure.c
    ${CMAKE_CURRENT_SOURCE_DIR}/compare/sample_compare.c)
  target_include_directories(sample_measure PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/freq
    ${CMAKE_CURRENT_SOURCE_DIR}/compare ${CMAKE_CURRENT_SOURCE_DIR}/render ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_definitions(sample_measure PRIVATE SAMPLE_MEASURE_BUILDING_SHARED)
  target_compile_options(sample_measure PRIVATE ${SAMPLE_WARNINGS})
  set_target_properties(texsample_render texsample_freq texsample_compare PROPERTIES POSITION_INDEPENDENT_CODE ON)
  add_dependencies(sample_measure texsample_render texsample_freq texsample_compare)
  target_link_libraries(sample_measure PRIVATE $<TARGET_FILE:texsample_compare> $<TARGET_FILE:texsample_freq>
    $<TARGET_FILE:texsample_render> sample_shared Threads::Threads m)
  if(TARGET sample_io_shared)
    target_link_libraries(sample_measure PRIVATE sample_io_shared)
  endif()
  # --exclude-libs: the renderer archive's symbols stay inside.
  target_link_options(sample_measure PRIVATE -Wl,--no-undefined -Wl,--exclude-libs,ALL)
  set_target_properties(sample_measure PROPERTIES C_VISIBILITY_PRESET hidden)
  # The API's own files serve this library only: out of texsample's glob
  # and texsample_freq's.
  get_target_property(_ts_sources texsample SOURCES)
  list(REMOVE_ITEM _ts_sources ${CMAKE_CURRENT_SOURCE_DIR}/compare/sample_compare.c)
  set_property(TARGET texsample PROPERTY SOURCES ${_ts_sources})
  get_target_property(_fq_sources texsample_freq SOURCES)
  list(REMOVE_ITEM _fq_sources ${CMAKE_CURRENT_SOURCE_DIR}/freq/sample_measure.c)
  set_property(TARGET texsample_freq PROPERTY SOURCES ${_fq_sources})
  install(TARGETS sample_measure LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
endif()
