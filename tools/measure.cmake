# libsample_measure: the tools' measurements as a shared library with a C
# API (tools/freq/sample_measure.h) for the Python package (doc/python.md).
# The frequency-test sources of texsample_freq (tools/freq.cmake), compiled
# once more as position-independent code and linked with the shared
# libsample, so a process holds one libsample and the textures a callback
# is handed are that library's. Only sample_freq_* is exported.
add_library(sample_measure SHARED ${TEXSAMPLE_FREQ_SOURCES})
target_include_directories(sample_measure PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/freq ${CMAKE_CURRENT_SOURCE_DIR})
target_compile_definitions(sample_measure PRIVATE SAMPLE_MEASURE_BUILDING_SHARED)
target_compile_options(sample_measure PRIVATE ${SAMPLE_WARNINGS})
target_link_libraries(sample_measure PRIVATE sample_shared m)
set_target_properties(sample_measure PROPERTIES C_VISIBILITY_PRESET hidden)
install(TARGETS sample_measure LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
