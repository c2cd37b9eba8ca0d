// Fuzz target: a glTF file, text or binary (GLB, recognised by its magic), loaded as `render model.gltf` does
// (load_scene: import_gltf, then the default camera and light) and rendered at 16 × 16.
#include "scenes/scene_build.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::expect_clean_errors([&] {
    const std::filesystem::path path = fuzz::input_file(data, size, "model.gltf");
    const scenes::Scene scene = scenes::load_scene(path);
    fuzz::render_tiny(scene);
  });
  return 0;
}
