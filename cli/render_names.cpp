// File-name patterns of render jobs (see render_names.h).
#include "cli/render_names.h"

#include <cctype>
#include <cstdio>
#include <filesystem>

#include "cli/cli_common.h"
#include "scenes/builtin_scenes.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

namespace {

constexpr std::string_view kScene = "{scene}";

// The frame field starting at `at` (a '%'): its length, and its zero-padded width (0: none). 0 length: not a
// field.
struct Field {
  size_t length = 0;
  int width = 0;
};

Field field_at(const std::string& p, size_t at) {
  size_t i = at + 1;
  int width = 0;
  bool zero = i < p.size() && p[i] == '0';
  while (i < p.size() && std::isdigit(static_cast<unsigned char>(p[i])) && width < 100) width = width * 10 + (p[i++] - '0');
  if (i < p.size() && p[i] == 'd' && width <= 12 && (width == 0 || zero)) return {i + 1 - at, width};
  return {};
}

}  // namespace

std::string scene_stem(const std::string& scene) {
  std::error_code ec;
  std::string s = std::filesystem::exists(scene, ec) ? std::filesystem::path(scene).stem().string() : scene;
  for (char& c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.')) c = '-';
  return s.empty() ? "scene" : s;
}

bool has_frame_field(const std::string& pattern, const std::string& option) {
  int fields = 0;
  for (size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') continue;
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      ++i;
      continue;
    }
    const Field f = field_at(pattern, i);
    if (f.length == 0)
      throw CliError(option, "'%' starts no frame field in '" + pattern + "' (use %d or %04d, and %% for '%')");
    ++fields;
    i += f.length - 1;
  }
  if (fields > 1) throw CliError(option, "more than one frame field in '" + pattern + "'");
  return fields == 1;
}

bool has_scene_field(const std::string& pattern) { return pattern.find(kScene) != std::string::npos; }

std::string expand_name(const std::string& pattern, const std::string& stem, int frame) {
  std::string out;
  for (size_t i = 0; i < pattern.size();) {
    if (pattern.compare(i, kScene.size(), kScene) == 0) {
      out += stem;
      i += kScene.size();
    } else if (pattern[i] == '%' && i + 1 < pattern.size() && pattern[i + 1] == '%') {
      out += '%';
      i += 2;
    } else if (const Field f = pattern[i] == '%' ? field_at(pattern, i) : Field{}; f.length) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%0*d", f.width, frame);
      out += buf;
      i += f.length;
    } else {
      out += pattern[i++];
    }
  }
  return out;
}

SHADOWLAB_ISA_END
}  // namespace cli
