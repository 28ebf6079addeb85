# oiio_replay (tools/bench/oiio_replay.cpp): re-times what `texsample bench
# --save` recorded. Its own program, linking OpenImageIO and nothing of ours
# (not the shim, not libsample), so that its timings and lookups are an
# independent check of bench's. Needs tools/oiio.cmake's OpenImageIO target
# (fragments are included in name order: oiio.cmake comes first).
set(_replay_src ${CMAKE_CURRENT_SOURCE_DIR}/bench/oiio_replay.cpp)
# texsample globbed tools/*/*.cpp; this file is not part of it.
get_target_property(_ts_sources texsample SOURCES)
list(REMOVE_ITEM _ts_sources ${_replay_src})
set_property(TARGET texsample PROPERTY SOURCES ${_ts_sources})
if(TARGET texsample_oiio AND DEFINED _oiio_lib)
  add_executable(oiio_replay ${_replay_src})
  target_compile_options(oiio_replay PRIVATE -Wall -Wextra -Wpedantic -Wshadow)
  target_link_libraries(oiio_replay PRIVATE ${_oiio_lib})
  # build/tools/bench/oiio_replay, beside the sources it replays.
  set_target_properties(oiio_replay PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/bench)
endif()
