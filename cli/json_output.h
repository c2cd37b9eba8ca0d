// `--json` output shared by render, inspect, diff, list and check: one JSON document on stdout, validated in the
// tests against the command's schema in docs/cli/ (valijson), and the version block every document carries.
#pragma once
#include <nlohmann/json.hpp>
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

// {"name": "shadowlab", "version": ..., "revision": ..., "simd": ...}: what produced a document or a golden.
nlohmann::json version_json();

// The version line of `shadowlab --version`.
std::string version_line();

// A number JSON can hold: NaN and infinities become null.
nlohmann::json json_number(double v);

// Prints `doc` (with "shadowlab": version_json() added) to stdout, indented, with a final newline.
void print_json(nlohmann::json doc);

SHADOWLAB_ISA_END
}  // namespace cli
