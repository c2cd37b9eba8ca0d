// The single test binary's entry point. Options beyond GoogleTest's own come from the environment:
// SHADOWLAB_TEST_THREADS (worker threads for pipeline tests, default: hardware) and SHADOWLAB_ASSETS
// (the glTF asset folder, default ../shared/assets beside the source tree).
#include <gtest/gtest.h>

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
