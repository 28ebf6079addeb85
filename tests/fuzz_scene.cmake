# libFuzzer target for the renderer's scene parser (doc/renderer.md, "Limits"); texsample_render
# is defined by tools/render.cmake, configured before tests/.
if(TARGET texsample_render)
  sample_add_fuzzer(fuzz_scene fuzz_scene.c corpus_scene texsample_render)
endif()
