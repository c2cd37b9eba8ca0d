# Tests of the llvmpipe reference itself (raster/reference/), included by tests/CMakeLists.txt. Adds nothing when
# the reference is not built (SHADOWLAB_GL_REFERENCE=OFF).
if(TARGET shadowlab::glref)
  list(APPEND SHADOWLAB_TEST_SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/gl_reference_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gl_sampling_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gl_timing_test.cpp)
  list(APPEND SHADOWLAB_TEST_LIBS shadowlab::glref)
endif()
