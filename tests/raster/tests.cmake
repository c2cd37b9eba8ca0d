# Tests of raster/: coverage, tie rule, clipping, depth formats, polygon offset, culling, viewport and scissor,
# interpolation, determinism across thread counts.
list(APPEND SHADOWLAB_TEST_SOURCES
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/coverage_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/clip_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/depth_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/depth_stage_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/state_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/setup_batch_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/assembly_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/depth_setup_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/quad_pair_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/clear_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/target_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/bins_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/tile_execution_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/hiz_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/srgb8_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/simd_records_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/simd_store_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/isa_namespace_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/thread_pool_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/raster/isa_select_test.cpp
)
list(APPEND SHADOWLAB_TEST_LIBS shadowlab::raster shadowlab_isa_select)
# Conformance against Mesa llvmpipe needs the GL reference (raster/reference/).
if(TARGET shadowlab::glref)
  list(APPEND SHADOWLAB_TEST_SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/raster/conformance_test.cpp)
  list(APPEND SHADOWLAB_TEST_LIBS shadowlab::glref shadowlab::scenes)
endif()
