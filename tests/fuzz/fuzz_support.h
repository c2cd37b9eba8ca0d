// What every fuzz target shares: the input as a file (the readers under test take paths, as the commands do),
// the errors a reader may answer with, and a tiny frame so whole-scene targets reach the rasterizer.
// Anything else escaping a target (std::out_of_range, std::bad_alloc, a sanitizer report) is a finding.
#pragma once
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "raster/renderer.h"
#include "scenes/frame/frame.h"
#include "scenes/io/io_error.h"
#include "scenes/scene.h"
#include "scenes/scene_error.h"
#include "shading/techniques/technique.h"

namespace fuzz {

// A folder of this process's own under the temporary directory (several fuzzers run side by side with -jobs);
// it is empty apart from the input, so relative references in a fuzzed file (glTF buffers, textures) miss.
// It is removed when the process exits normally (libFuzzer ends a run with exit()); a crash leaves it, with the
// input that caused it. run.sh points TMPDIR at /dev/shm: writing each input to a disk file cost more than
// reading it (ext4's truncate on every open), 5x in fuzz_image_input.
inline const std::filesystem::path& work_dir() {
  struct Folder {
    std::filesystem::path path;
    Folder() : path(std::filesystem::temp_directory_path() / ("shadowlab-fuzz-" + std::to_string(getpid()))) {
      std::filesystem::create_directories(path);
    }
    ~Folder() {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  };
  static const Folder folder;
  return folder.path;
}

// Writes the input to work_dir()/name and returns the path.
inline std::filesystem::path input_file(const uint8_t* data, size_t size, const std::string& name) {
  const std::filesystem::path path = work_dir() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  out.close();
  if (!out) throw std::runtime_error("fuzz harness: cannot write " + path.string());
  return path;
}

// Runs `body`, accepting exactly the errors that name what the user gave, by their own types: SceneError,
// IoError, FrameError and TechniqueError (each names the file and field or the option). `Extra` adds one more
// accepted type (CliError for the cli/ readers). Not accepted, so a finding: a bare std::invalid_argument (the
// modules throw those only for a caller's broken precondition), and raster's DrawError and TargetSizeError,
// whose wording is the pipeline's ("width 0 is outside 1..16384"): the tiny frame asks for small targets only,
// so reaching either means a technique computed a bad draw or size from the scene instead of refusing it.
template <typename Extra = scenes::SceneError, typename Body>
void expect_clean_errors(Body&& body) {
  try {
    body();
  } catch (const Extra&) {
  } catch (const scenes::SceneError&) {
  } catch (const scenes::io::IoError&) {
  } catch (const frame::FrameError&) {
  } catch (const shading::tech::TechniqueError&) {
  }
}

// Renders every light's shadow and the camera pass at 16 × 16 with 32-texel maps, inline (no worker
// threads): NaN, infinite, huge and degenerate geometry reaches clipping, setup and the depth passes while one
// run stays in the milliseconds. The scene's own map sizes are checked by resolve_light before the override.
inline void render_tiny(const scenes::Scene& scene) {
  static raster::Renderer renderer(0);
  frame::FrameConfig config;
  config.width = 16;
  config.height = 16;
  config.map_size = 32;
  config.export_maps = true;
  const frame::Frame f = frame::render_frame(scene, config, renderer);
  (void)frame::export_maps(f);
}

}  // namespace fuzz
