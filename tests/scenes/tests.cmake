# Tests of scenes/ (scene model, JSON format, glTF import, built-in scenes) and of scenes/io/ (EXR maps, PNG
# frames, material textures, checked with OpenEXR and OpenImageIO directly), included by tests/CMakeLists.txt.
list(APPEND SHADOWLAB_TEST_SOURCES
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/builtin_scenes_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/gltf_assets_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/gltf_import_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/gltf_pose_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/mesh_ops_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/scene_schema_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/primitives_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/scene_errors_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/scene_json_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/scene_queries_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/shadow_settings_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/stage_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/io_atomic_write_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/io_exr_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/io_exr_image_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/io_png_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/io_texture_test.cpp
)
list(APPEND SHADOWLAB_TEST_LIBS shadowlab::scenes shadowlab::io OpenEXR::OpenEXR OpenImageIO::OpenImageIO)
