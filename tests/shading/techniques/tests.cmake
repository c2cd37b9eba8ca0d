# Tests of shading/techniques/: analytic shadow-map cases (shadow area, PCF ramp, acne against
# slope bias), golden-image hashes of whole frames (scenes/frame) of the tutorial steps at several thread counts, and the bias measurements.
list(APPEND SHADOWLAB_TEST_SOURCES
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/classic_analytic_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/classic_x8_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/frustum_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/golden_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/bias_measure_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/projective_map_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/projective_outline_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/offset_blur_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/fade_table_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/param_use_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/omni_map_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/omni_agreement_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/omni_density_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/omni_golden_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/view_following_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/view_following_frame_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/filtered_analytic_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/cascade_moments_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/cube_moments_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/moment_mips_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/filtered_golden_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/pcss_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/cascade_pcss_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/cube_pcss_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/tutorial_poisson_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/tutorial_fit_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/irregular_cube_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/irregular_lists_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/shading/techniques/irregular_test.cpp
)
# irregular_test.cpp scores frames against the ray-cast reference (scenes/reference), so a build of this module
# alone links that library too.
list(APPEND SHADOWLAB_TEST_LIBS shadowlab::techniques shadowlab::frame shadowlab::reference)
