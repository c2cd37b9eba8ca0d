// The per-frame JSON record of `render` (see frame_record.h).
#include "cli/frame_record.h"

#include <cstdint>
#include <cstdio>

#include "shading/techniques/vocabulary.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

std::string pixel_hash(const raster::ColorTarget& c) {
  uint64_t h = 1469598103934665603ull;
  for (int y = 0; y < c.height(); ++y) {
    const uint8_t* row = c.row8(y);
    for (int x = 0; x < c.width() * 4; ++x) h = (h ^ row[x]) * 1099511628211ull;
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", (unsigned long long)h);
  return buf;
}

nlohmann::json frame_json(int number, double total_ms, const frame::Frame& f, const frame::FrameConfig& config) {
  const frame::FrameStats& s = f.stats;
  nlohmann::json maps = nlohmann::json::array();
  for (const frame::LightResult& l : f.lights) {
    if (!l.shadow) continue;
    for (const shading::tech::MapRecord& r : l.shadow->maps())
      maps.push_back({{"light", l.name},
                      {"technique", r.technique},
                      {"width", r.target->width()},
                      {"height", r.target->height()},
                      {"depth_format", raster::to_string(r.target->format())}});
  }
  for (size_t m = 0; m < f.projective.maps.size(); ++m)
    maps.push_back({{"light", f.projective.map_names[m]},
                    {"technique", "projective"},
                    {"width", f.projective.maps[m].width},
                    {"height", f.projective.maps[m].height},
                    {"depth_format", f.projective.maps[m].depth_format}});
  nlohmann::json aliasing = nlohmann::json::array();
  for (size_t i = 0; i < f.aliasing.size(); ++i)
    if (f.aliasing[i].measured)
      aliasing.push_back({{"light", f.lights[i].name},
                          {"max", f.aliasing[i].max},
                          {"p95", f.aliasing[i].p95},
                          {"mean", f.aliasing[i].mean},
                          {"pixels", f.aliasing[i].measured}});
  nlohmann::json j = {{"frame", number},
                      {"total_ms", total_ms},
                      {"shadow_ms", s.shadow_ms},
                      {"camera_ms", s.camera_ms},
                      {"maps_rendered", s.maps_rendered},
                      {"triangles", s.draws.triangles},
                      {"setups", s.draws.setups},
                      {"clipped", s.draws.clipped},
                      {"culled", s.draws.culled},
                      {"rejected", s.draws.rejected},
                      {"width", config.width},
                      {"height", config.height},
                      {"pixels", size_t(config.width) * size_t(config.height)},
                      {"hash", pixel_hash(f.color)},
                      {"ev100", f.ev100},
                      {"maps", maps},
                      {"aliasing", aliasing},
                      {"outputs", nlohmann::json::array()}};
  if (s.projective.active)
    j["projective"] = {{"maps_rebuilt", s.projective.maps_rebuilt},
                       {"maps_reused", s.projective.maps_reused},
                       {"maps_skipped", s.projective.maps_skipped}};
  nlohmann::json technique_stats = nlohmann::json::array();
  for (const frame::LightResult& l : f.lights) {
    if (!l.shadow) continue;
    nlohmann::json figures = nlohmann::json::object();
    for (const shading::tech::TechniqueStat& t : l.shadow->stats()) figures[t.name] = t.value;
    if (!figures.empty())
      technique_stats.push_back(
          {{"light", l.name}, {"technique", shading::tech::to_string(l.technique)}, {"stats", figures}});
  }
  if (!technique_stats.empty()) j["technique_stats"] = technique_stats;
  return j;
}

SHADOWLAB_ISA_END
}  // namespace cli
