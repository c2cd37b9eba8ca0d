# Whole frames through the scenes/frame library: every built-in scene, per-light settings, the camera pass's two
# fragment paths, projective frames, and the registry walk over every technique and light type.
list(APPEND SHADOWLAB_TEST_SOURCES ${CMAKE_CURRENT_LIST_DIR}/builtin_render_test.cpp
     ${CMAKE_CURRENT_LIST_DIR}/aliasing_test.cpp
     ${CMAKE_CURRENT_LIST_DIR}/frame_lights_test.cpp
     ${CMAKE_CURRENT_LIST_DIR}/camera_pair_test.cpp
     ${CMAKE_CURRENT_LIST_DIR}/projective_frame_test.cpp
     ${CMAKE_CURRENT_LIST_DIR}/bad_geometry_test.cpp
     ${CMAKE_CURRENT_LIST_DIR}/material_frame_test.cpp
     ${CMAKE_CURRENT_LIST_DIR}/develop_test.cpp)
list(APPEND SHADOWLAB_TEST_LIBS shadowlab::frame OpenImageIO::OpenImageIO)
# The registry walk also runs the executable (tests/cli/cli_run.h), whose path the cli module defines: a partial
# build without that module leaves it out rather than failing to compile.
if(TARGET shadowlab AND "cli" IN_LIST SHADOWLAB_TEST_MODULES)
  list(APPEND SHADOWLAB_TEST_SOURCES ${CMAKE_CURRENT_LIST_DIR}/registry_walk_test.cpp)
endif()
