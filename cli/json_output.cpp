// The version block and JSON printing (see json_output.h).
#include "cli/json_output.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "shadowlab_revision.h"

#ifndef SHADOWLAB_VERSION
#define SHADOWLAB_VERSION "unknown"
#endif
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

namespace {

// The SIMD path the pipeline's stages were compiled for (raster/simd/vec.h chooses at compile time).
const char* simd_path() { return SHADOWLAB_ISA_NAME; }

}  // namespace

nlohmann::json version_json() {
  return {{"name", "shadowlab"}, {"version", SHADOWLAB_VERSION}, {"revision", SHADOWLAB_REVISION}, {"simd", simd_path()}};
}

std::string version_line() {
  return std::string("shadowlab ") + SHADOWLAB_VERSION + " (revision " + SHADOWLAB_REVISION + ", SIMD path " +
         simd_path() + ")";
}

nlohmann::json json_number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

void print_json(nlohmann::json doc) {
  doc["shadowlab"] = version_json();
  const std::string text = doc.dump(2) + "\n";
  std::fwrite(text.data(), 1, text.size(), stdout);
  std::fflush(stdout);
}

SHADOWLAB_ISA_END
}  // namespace cli
