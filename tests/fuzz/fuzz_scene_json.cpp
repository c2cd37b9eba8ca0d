// Fuzz target: a JSON scene document, parsed (parse_scene_json), built (build_scene: primitives, hierarchy,
// lights) and rendered at 16 × 16 with every light's shadow technique.
#include "scenes/scene_build.h"
#include "scenes/scene_json.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  fuzz::expect_clean_errors([&] {
    const scenes::SceneDesc desc = scenes::parse_scene_json(text, "fuzz.json");
    const scenes::Scene scene = scenes::build_scene(desc, {fuzz::work_dir(), "fuzz.json"});
    fuzz::render_tiny(scene);
  });
  return 0;
}
