// `shadowlab inspect FILE...`: what depth maps and frames hold. For an EXR: size, channels, the depth channel
// chosen (image_input.h), its range and coverage, the header's technique, format, encoding and matrices ("unset"
// where the file has none) and per-pass data, plus an optional false-colour preview with a stated colour map
// and range. For a PNG frame: size, channels and each channel's range and mean. Each file is described as one
// JSON object; `--json` prints them as they are, otherwise they are printed as text.
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <OpenImageIO/imagebufalgo.h>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "cli/cli_common.h"
#include "cli/image_input.h"
#include "cli/json_output.h"
#include "cli/map_stats.h"
#include "raster/limits.h"
#include "scenes/io/exr_map.h"
#include "scenes/io/png_frame.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN
namespace {

struct InspectArgs {
  std::vector<std::string> files;
  std::string png, channel, range;
  bool json = false;
};

// A matrix as the 16 values in glm::value_ptr order, the layout light matrix files use (so it can be pasted);
// null when the file does not carry it.
nlohmann::json matrix_json(bool present, const glm::mat4& m) {
  if (!present) return nullptr;
  const float* v = glm::value_ptr(m);
  return std::vector<double>(v, v + 16);
}

nlohmann::json or_null(const std::string& s) { return s.empty() ? nlohmann::json(nullptr) : nlohmann::json(s); }

// Where file `index` of `count` gets its preview: --png itself for one file, DIR/<stem>.png for several.
std::filesystem::path preview_path(const InspectArgs& a, const std::string& file) {
  if (a.files.size() == 1) return a.png;
  return std::filesystem::path(a.png) / (std::filesystem::path(file).stem().string() + ".png");
}

nlohmann::json inspect_map(const InspectArgs& a, const std::string& file, std::optional<std::pair<float, float>> range,
                           scenes::io::WriteBatch& previews) {
  const std::vector<std::string> channels = scenes::io::exr_channel_names(file);
  const ChannelChoice choice = choose_depth_channel(channels, a.channel, file);
  const scenes::io::ExrMap map = scenes::io::read_exr_map(file, choice.name);
  const MapStats s = map_stats(map);
  nlohmann::json j = {{"file", file},
                      {"kind", "depth map"},
                      {"format", "exr"},
                      {"width", map.width},
                      {"height", map.height},
                      {"channels", channels},
                      {"channel", choice.name},
                      {"channel_reason", choice.reason},
                      {"technique", or_null(map.technique)},
                      {"depth_format", or_null(map.depth_format)},
                      {"encoding", or_null(map.encoding)},
                      {"texels", s.texels},
                      {"nan_texels", s.nan},
                      {"min", s.texels > s.nan ? json_number(s.min) : nlohmann::json(nullptr)},
                      {"max", s.texels > s.nan ? json_number(s.max) : nlohmann::json(nullptr)},
                      {"covered_texels", s.covered},
                      {"coverage", s.coverage()},
                      {"covered_min", s.covered ? json_number(s.covered_min) : nlohmann::json(nullptr)},
                      {"covered_max", s.covered ? json_number(s.covered_max) : nlohmann::json(nullptr)},
                      {"world_to_camera", matrix_json(map.has_world_to_camera, map.world_to_camera)},
                      {"world_to_ndc", matrix_json(map.has_world_to_ndc, map.world_to_ndc)}};
  nlohmann::json passes = nlohmann::json::array();
  for (const scenes::io::MapPass& p : map.passes)
    passes.push_back({{"label", or_null(p.label)},
                      {"viewport", {p.viewport.x, p.viewport.y, p.viewport.width, p.viewport.height}},
                      {"world_to_camera", matrix_json(true, p.world_to_camera)},
                      {"world_to_ndc", matrix_json(true, p.world_to_ndc)}});
  j["passes"] = passes;
  j["preview"] = nullptr;
  if (!a.png.empty()) {
    // A map from elsewhere may exceed what a frame target holds (issue 23: 16385 x 1 failed with the target's
    // internal wording).
    if (map.width > raster::kMaxTargetSize || map.height > raster::kMaxTargetSize)
      throw CliError("--png", "a preview of a " + std::to_string(map.width) + " x " + std::to_string(map.height) +
                                  " map is larger than " + std::to_string(raster::kMaxTargetSize) +
                                  " pixels a side; inspect without --png for the statistics");
    // The covered range unless --range fixes one (the same scale across several maps).
    const float lo = range ? range->first : (s.covered ? s.covered_min : 0.0f);
    const float hi = range ? range->second : (s.covered ? s.covered_max : 1.0f);
    const std::filesystem::path out = preview_path(a, file);
    scenes::io::write_png(previews, out, false_colour(map, lo, hi));
    j["preview"] = {{"file", out.string()}, {"colour_map", kPreviewColourMap}, {"range", {lo, hi}}};
  }
  return j;
}

nlohmann::json inspect_frame(const InspectArgs& a, const std::string& file) {
  if (!a.png.empty()) throw CliError("--png", file + " is a frame: previews are for depth maps");
  if (!a.channel.empty()) throw CliError("--channel", file + " is a frame: --channel picks a depth map's channel");
  int bits = 0;
  const OIIO::ImageBuf img = read_image(file, &bits);
  const OIIO::ImageSpec& spec = img.spec();
  const OIIO::ImageBufAlgo::PixelStats st = OIIO::ImageBufAlgo::computePixelStats(img);
  nlohmann::json channels = nlohmann::json::array();
  for (int c = 0; c < spec.nchannels; ++c)
    channels.push_back({{"name", spec.channel_name(c)},
                        {"min", json_number(st.min[size_t(c)])},
                        {"max", json_number(st.max[size_t(c)])},
                        {"mean", json_number(st.avg[size_t(c)])}});
  return {{"file", file},
          {"kind", "frame"},
          {"format", "png"},
          {"width", spec.width},
          {"height", spec.height},
          {"bits_per_channel", bits},
          {"colour_space", spec.get_string_attribute("oiio:ColorSpace", "unknown")},
          {"channels", channels}};
}

std::string matrix_text(const nlohmann::json& m) {
  if (m.is_null()) return "unset";
  std::string s = "[";
  for (size_t i = 0; i < m.size(); ++i) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%s%.9g", i ? ", " : "", m[i].get<double>());
    s += buf;
  }
  return s + "]";
}

std::string value_text(const nlohmann::json& v) {
  if (v.is_null()) return "unset";
  if (v.is_string()) return v.get<std::string>();
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v.get<double>());
  return buf;
}

void print_text(const nlohmann::json& j) {
  std::printf("file: %s\n", j["file"].get<std::string>().c_str());
  std::printf("size: %dx%d\n", j["width"].get<int>(), j["height"].get<int>());
  if (j["kind"] == "frame") {
    std::printf("kind: frame (PNG, %d bits per channel, colour space %s)\n", j["bits_per_channel"].get<int>(),
                j["colour_space"].get<std::string>().c_str());
    for (const auto& c : j["channels"])
      std::printf("channel %s: min %s, max %s, mean %s\n", c["name"].get<std::string>().c_str(),
                  value_text(c["min"]).c_str(), value_text(c["max"]).c_str(), value_text(c["mean"]).c_str());
    return;
  }
  std::string channels;
  for (const auto& c : j["channels"]) channels += (channels.empty() ? "" : ", ") + c.get<std::string>();
  std::printf("kind: depth map (EXR)\n");
  std::printf("channels: %s\n", channels.c_str());
  std::printf("depth channel: %s (%s)\n", j["channel"].get<std::string>().c_str(),
              j["channel_reason"].get<std::string>().c_str());
  std::printf("technique: %s\n", value_text(j["technique"]).c_str());
  std::printf("depth format: %s\n", value_text(j["depth_format"]).c_str());
  std::printf("encoding: %s\n", value_text(j["encoding"]).c_str());
  std::printf("depth: min %s, max %s\n", value_text(j["min"]).c_str(), value_text(j["max"]).c_str());
  if (j["nan_texels"].get<size_t>()) std::printf("NaN texels: %zu\n", j["nan_texels"].get<size_t>());
  if (j["covered_texels"].get<size_t>())
    std::printf("covered depth: min %s, max %s\n", value_text(j["covered_min"]).c_str(),
                value_text(j["covered_max"]).c_str());
  std::printf("coverage: %.6f (%zu of %zu texels < 1)\n", j["coverage"].get<double>(),
              j["covered_texels"].get<size_t>(), j["texels"].get<size_t>());
  std::printf("worldToCamera: %s\n", matrix_text(j["world_to_camera"]).c_str());
  std::printf("worldToNDC: %s\n", matrix_text(j["world_to_ndc"]).c_str());
  std::printf("passes: %zu\n", j["passes"].size());
  for (size_t i = 0; i < j["passes"].size(); ++i) {
    const auto& p = j["passes"][i];
    std::printf("pass %zu: label %s, viewport %d %d %d %d\n", i, value_text(p["label"]).c_str(),
                p["viewport"][0].get<int>(), p["viewport"][1].get<int>(), p["viewport"][2].get<int>(),
                p["viewport"][3].get<int>());
    std::printf("pass %zu worldToCamera: %s\n", i, matrix_text(p["world_to_camera"]).c_str());
    std::printf("pass %zu worldToNDC: %s\n", i, matrix_text(p["world_to_ndc"]).c_str());
  }
  if (!j["preview"].is_null())
    std::printf("preview: %s (colour map %s; range %s to %s)\n", j["preview"]["file"].get<std::string>().c_str(),
                kPreviewColourMap, value_text(j["preview"]["range"][0]).c_str(),
                value_text(j["preview"]["range"][1]).c_str());
}

int run_inspect(const InspectArgs& a) {
  std::optional<std::pair<float, float>> range;
  if (!a.range.empty()) {
    if (a.png.empty()) throw CliError("--range", "only applies to --png previews");
    range = parse_float_pair(a.range, "--range", "LOW,HIGH");
    if (!(range->second > range->first)) throw CliError("--range", "expected LO,HI with LO < HI");
  }
  if (!a.png.empty()) {
    if (a.files.size() == 1) {
      if (lower_extension(a.png) != ".png") throw CliError("--png", "expected a .png file name");
      check_output_dir(a.png, "--png");
    } else {
      std::error_code ec;
      if (std::filesystem::exists(a.png, ec) && !std::filesystem::is_directory(a.png, ec))
        throw CliError("--png", "with several files, --png names a directory for the previews; " + a.png +
                                    " is a file");
      check_output_dir(a.png, "--png");  // the folder it goes in; the folder itself is created
    }
  }
  for (const std::string& f : a.files) image_kind(f);  // every file checked before any work
  if (!a.png.empty() && a.files.size() > 1) {  // no preview replaces another's (a/light0.exr and b/light0.exr)
    std::map<std::filesystem::path, std::string> owner;
    for (const std::string& f : a.files)
      if (const auto [it, fresh] = owner.emplace(preview_path(a, f), f); !fresh)
        throw CliError(f, "its preview " + it->first.string() + " would replace " + it->second +
                              "'s (the previews are named by the files' stems; inspect them apart)");
  }
  // Previews are staged and written together once every file has been read: a bad file writes none (and a
  // preview directory this run created is removed again).
  std::filesystem::path created_dir;
  nlohmann::json files = nlohmann::json::array();
  try {
    scenes::io::WriteBatch previews;
    if (!a.png.empty() && a.files.size() > 1) {
      std::error_code ec;
      if (!std::filesystem::exists(a.png, ec)) {
        std::filesystem::create_directories(a.png, ec);
        if (ec) throw CliError("--png", "cannot create directory " + a.png + " (" + ec.message() + ")");
        created_dir = a.png;
      }
    }
    for (const std::string& f : a.files)
      files.push_back(image_kind(f) == ImageKind::exr ? inspect_map(a, f, range, previews) : inspect_frame(a, f));
    previews.commit();
  } catch (...) {
    std::error_code ec;
    if (!created_dir.empty()) std::filesystem::remove(created_dir, ec);  // only if it is still empty
    throw;
  }
  if (a.json) {
    print_json({{"command", "inspect"}, {"files", files}});
  } else {
    for (size_t i = 0; i < files.size(); ++i) {
      if (i) std::printf("\n");
      print_text(files[i]);
    }
  }
  return 0;
}

}  // namespace

Command add_inspect_command(CLI::App& parent) {
  auto args = std::make_shared<InspectArgs>();
  CLI::App* app = parent.add_subcommand(
      "inspect", "Describe depth maps (EXR, from shadowlab or any renderer) and PNG frames; preview maps");
  app->add_option("files", args->files, "EXR depth maps and PNG frames")->required();
  app->add_option("--channel", args->channel,
                  "The EXR channel holding depth (default: the only channel, else Z, else *.Z, else R, else Y)");
  app->add_option("--png", args->png,
                  "Write a false-colour preview PNG of each map (several files: a directory of <stem>.png)");
  app->add_option("--range", args->range, "LO,HI: the preview's depth range (default: each map's covered range)");
  app->add_flag("--json", args->json, "Print JSON (docs/cli/inspect.schema.json) instead of text");
  return {app, [args] { return run_inspect(*args); }};
}

SHADOWLAB_ISA_END
}  // namespace cli
