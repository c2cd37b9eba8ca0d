# scenes/ (the scene model, JSON and glTF loaders, built-in procedural scenes): target shadowlab_scenes.
# Included from scenes/CMakeLists.txt. tinygltf's implementation is compiled here (tinygltf_impl.cpp) without
# stb_image: images are never decoded, so the defines below must reach every file that includes tiny_gltf.h.
find_package(nlohmann_json CONFIG REQUIRED)

add_library(shadowlab_scenes
  ${CMAKE_CURRENT_SOURCE_DIR}/builtin_duel.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/builtin_point_lights.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/builtin_projective.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/builtin_scenes.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/builtin_tutorial.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/camera_math.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/gltf_accessors.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/gltf_import.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/json_geometry_read.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/json_in.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/mesh_ops.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/primitives.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scene_build.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scene_desc.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scene_json_read.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scene_json_write.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/scene_queries.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shadow_settings.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/tinygltf_impl.cpp
)
add_library(shadowlab::scenes ALIAS shadowlab_scenes)
target_include_directories(shadowlab_scenes PUBLIC ${PROJECT_SOURCE_DIR})
target_link_libraries(shadowlab_scenes
  PUBLIC glm::glm shadowlab_options
  PRIVATE shadowlab_warnings nlohmann_json::nlohmann_json)
target_compile_definitions(shadowlab_scenes PRIVATE
  TINYGLTF_NO_STB_IMAGE TINYGLTF_NO_STB_IMAGE_WRITE TINYGLTF_NO_EXTERNAL_IMAGE)
# Third-party code: not held to our warning flags.
set_source_files_properties(${CMAKE_CURRENT_SOURCE_DIR}/tinygltf_impl.cpp PROPERTIES COMPILE_OPTIONS "-w")
