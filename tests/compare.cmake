# texsample compare (tools/compare): its metrics as a unit, then the
# command end to end (ground-truth convergence, ordering of the filters on
# the plane, outputs, exit codes), then the HTML page in headless Chromium.
if(TARGET texsample_compare)
  add_executable(compare_metrics ${CMAKE_CURRENT_SOURCE_DIR}/compare_metrics.c)
  target_link_libraries(compare_metrics PRIVATE texsample_compare)
  target_compile_options(compare_metrics PRIVATE ${SAMPLE_WARNINGS})
  add_test(NAME compare_metrics COMMAND compare_metrics)

  # compare's own scenes through the per-pixel queries (no texsample run).
  add_executable(compare_scenes ${CMAKE_CURRENT_SOURCE_DIR}/compare_scenes.c)
  target_include_directories(compare_scenes PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_link_libraries(compare_scenes PRIVATE texsample_compare)
  target_compile_options(compare_scenes PRIVATE ${SAMPLE_WARNINGS})
  add_test(NAME compare_scenes COMMAND compare_scenes)
  set_tests_properties(compare_scenes PROPERTIES SKIP_RETURN_CODE 77)
endif()

if(TARGET texsample)
  add_executable(compare_cli ${CMAKE_CURRENT_SOURCE_DIR}/compare_cli.c)
  target_include_directories(compare_cli PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_link_libraries(compare_cli PRIVATE m)
  target_compile_options(compare_cli PRIVATE ${SAMPLE_WARNINGS})
  add_test(NAME compare_cli COMMAND compare_cli $<TARGET_FILE:texsample>
           ${CMAKE_CURRENT_BINARY_DIR}/compare_cli.out)
  set_tests_properties(compare_cli PROPERTIES TIMEOUT 600)

  add_test(NAME compare_html COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/compare_html.sh
           $<TARGET_FILE:texsample> ${CMAKE_CURRENT_BINARY_DIR}/compare_html.out)
  # OpenImageIO 2.4 deletes its TextureSystem through a pointer of another
  # size (inside the library); ASan would stop there under SAMPLE_SANITIZE.
  set_tests_properties(compare_html PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300
    ENVIRONMENT "ASAN_OPTIONS=new_delete_type_mismatch=0")
endif()

# compare's view, truth, runs, stochastic sweep and plots (texsample's own
# library, tools/compare.cmake) called on tiny scenes: solid textures baked
# into 3D textures (tests/compare_solid.c) and the stochastic sweep with its
# plot (tests/compare_spp.c).
if(TARGET texsample_compare)
  foreach(t compare_solid compare_spp)
    add_executable(${t} ${CMAKE_CURRENT_SOURCE_DIR}/${t}.c)
    target_include_directories(${t} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
    target_link_libraries(${t} PRIVATE texsample_compare)
    target_compile_options(${t} PRIVATE ${SAMPLE_WARNINGS})
  endforeach()
  add_test(NAME compare_solid COMMAND compare_solid)
  add_test(NAME compare_spp COMMAND compare_spp ${CMAKE_CURRENT_BINARY_DIR}/compare_spp_out)
  set_tests_properties(compare_spp PROPERTIES SKIP_RETURN_CODE 77)
endif()
