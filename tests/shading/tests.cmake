# Tests of shading/ (textures, samplers, lookups, cube maps, lighting) and of scenes/io/ (EXR maps, PNG frames,
# material textures; listed here because tests/scenes/tests.cmake belongs to the scene tests).
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
  shading/wrap_test.cpp
  scenes/io_exr_test.cpp
  scenes/io_png_test.cpp
  scenes/io_texture_test.cpp
)
list(APPEND SHADOWLAB_TEST_LIBS shadowlab::shading shadowlab::io OpenEXR::OpenEXR OpenImageIO::OpenImageIO)
# Sampling conformance against llvmpipe needs the GL reference (raster/reference/).
if(TARGET shadowlab::glref)
  list(APPEND SHADOWLAB_TEST_SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/shading/sampling_conformance_test.cpp)
  list(APPEND SHADOWLAB_TEST_LIBS shadowlab::glref)
endif()
