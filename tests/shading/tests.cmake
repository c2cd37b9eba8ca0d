# Tests of shading/ (textures, samplers, lookups, cube maps, lighting), included by tests/CMakeLists.txt.
list(APPEND SHADOWLAB_TEST_SOURCES
  shading/compare_test.cpp
  shading/cube_test.cpp
  shading/filter_test.cpp
  shading/lighting_test.cpp
  shading/lod_test.cpp
  shading/mip_chain_test.cpp
  shading/pcf_simd_test.cpp
  shading/proj_test.cpp
  shading/shadow_lookup_test.cpp
  shading/texel_format_test.cpp
  shading/texture_test.cpp
  shading/tone_map_test.cpp
  shading/wrap_test.cpp
)
list(APPEND SHADOWLAB_TEST_LIBS shadowlab::shading)
# Sampling conformance against llvmpipe needs the GL reference (raster/reference/).
if(TARGET shadowlab::glref)
  list(APPEND SHADOWLAB_TEST_SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/shading/sampling_conformance_test.cpp)
  list(APPEND SHADOWLAB_TEST_LIBS shadowlab::glref)
endif()
