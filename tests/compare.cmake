# texsample compare (tools/compare): its metrics as a unit, then the
# command end to end (ground-truth convergence, ordering of the filters on
# the plane, outputs, exit codes), then the HTML page in headless Chromium.
add_executable(compare_metrics ${CMAKE_CURRENT_SOURCE_DIR}/compare_metrics.c
                               ${PROJECT_SOURCE_DIR}/tools/compare/metrics.c
                               ${PROJECT_SOURCE_DIR}/tools/compare/legend.c
                               ${PROJECT_SOURCE_DIR}/tools/compare/font.c)
target_include_directories(compare_metrics PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}
                           ${PROJECT_SOURCE_DIR}/tools ${PROJECT_SOURCE_DIR}/tools/compare)
target_link_libraries(compare_metrics PRIVATE sample m)
target_compile_options(compare_metrics PRIVATE ${SAMPLE_WARNINGS})
add_test(NAME compare_metrics COMMAND compare_metrics)

# compare's own scenes through the per-pixel queries (no texsample run).
if(TARGET texsample_render)
  add_executable(compare_scenes ${CMAKE_CURRENT_SOURCE_DIR}/compare_scenes.c
                 ${PROJECT_SOURCE_DIR}/tools/compare/scenes.c ${PROJECT_SOURCE_DIR}/tools/compare/view.c)
  target_include_directories(compare_scenes PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}
                             ${PROJECT_SOURCE_DIR}/tools ${PROJECT_SOURCE_DIR}/tools/compare)
  target_link_libraries(compare_scenes PRIVATE texsample_render m)
  target_compile_options(compare_scenes PRIVATE ${SAMPLE_WARNINGS})
  # The photograph of the teapot-image scene, as in tools/compare.cmake.
  target_compile_definitions(compare_scenes PRIVATE TEXSAMPLE_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
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

# Solid textures baked into 3D textures, through compare's view, truth and
# runs on a tiny scene (tests/compare_solid.c).
if(TARGET texsample_render)
  set(_solid_sources configs view run backends truth metrics)
  list(TRANSFORM _solid_sources PREPEND ${PROJECT_SOURCE_DIR}/tools/compare/)
  list(TRANSFORM _solid_sources APPEND .c)
  add_executable(compare_solid ${CMAKE_CURRENT_SOURCE_DIR}/compare_solid.c ${_solid_sources}
                 ${PROJECT_SOURCE_DIR}/tools/cli.c)
  target_include_directories(compare_solid PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}
                             ${PROJECT_SOURCE_DIR}/tools ${PROJECT_SOURCE_DIR}/tools/compare)
  target_link_libraries(compare_solid PRIVATE texsample_freq texsample_render m)
  target_compile_options(compare_solid PRIVATE ${SAMPLE_WARNINGS})
  add_test(NAME compare_solid COMMAND compare_solid)
endif()

# compare's stochastic sweep (RMSE against samples per pixel) and its plot
# on a tiny plane (tests/compare_spp.c).
if(TARGET texsample_render)
  set(_spp_sources configs scenes view run backends truth metrics stochastic cost picture font
    legend report)
  list(TRANSFORM _spp_sources PREPEND ${PROJECT_SOURCE_DIR}/tools/compare/)
  list(TRANSFORM _spp_sources APPEND .c)
  add_executable(compare_spp ${CMAKE_CURRENT_SOURCE_DIR}/compare_spp.c ${_spp_sources}
                 ${PROJECT_SOURCE_DIR}/tools/cli.c)
  target_include_directories(compare_spp PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}
                             ${PROJECT_SOURCE_DIR}/tools ${PROJECT_SOURCE_DIR}/tools/compare)
  target_compile_definitions(compare_spp PRIVATE TEXSAMPLE_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  target_link_libraries(compare_spp PRIVATE texsample_freq texsample_render m)
  target_compile_options(compare_spp PRIVATE ${SAMPLE_WARNINGS})
  add_test(NAME compare_spp COMMAND compare_spp ${CMAKE_CURRENT_BINARY_DIR}/compare_spp_out)
  set_tests_properties(compare_spp PROPERTIES SKIP_RETURN_CODE 77)
endif()
