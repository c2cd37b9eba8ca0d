# Tests of scenes/ (scene model, JSON format, glTF import, built-in scenes), included by tests/CMakeLists.txt.
list(APPEND SHADOWLAB_TEST_SOURCES
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/builtin_scenes_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/gltf_assets_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/gltf_import_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/mesh_ops_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/primitives_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/scene_errors_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/scene_json_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/scene_queries_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scenes/shadow_settings_test.cpp
)
list(APPEND SHADOWLAB_TEST_LIBS shadowlab::scenes)
# The image-file tests of scenes/io/ (io_*_test.cpp) list themselves in io_tests.cmake when it exists.
include(${CMAKE_CURRENT_LIST_DIR}/io_tests.cmake OPTIONAL)
