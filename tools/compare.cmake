# texsample compare (tools/compare/): its own scenes read the photograph
# from testimages/ of this source tree, as the renderer's built-in scenes do
# (tools/render.cmake).
set_property(SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/compare/scenes.c APPEND PROPERTY
  COMPILE_DEFINITIONS TEXSAMPLE_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
