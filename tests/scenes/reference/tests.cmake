# The exact ray-cast reference and the error report (scenes/reference/): analytic shadows against the rays,
# determinism across thread counts, scoring rules, and shadow maps converging on the reference as they grow.
list(APPEND SHADOWLAB_TEST_SOURCES ${CMAKE_CURRENT_LIST_DIR}/exact_visibility_test.cpp
     ${CMAKE_CURRENT_LIST_DIR}/shadow_score_test.cpp
     ${CMAKE_CURRENT_LIST_DIR}/convergence_test.cpp
     ${CMAKE_CURRENT_LIST_DIR}/error_map_test.cpp
     ${CMAKE_CURRENT_LIST_DIR}/shimmer_test.cpp
     ${CMAKE_CURRENT_LIST_DIR}/masked_occlusion_test.cpp)
list(APPEND SHADOWLAB_TEST_LIBS shadowlab::reference)
