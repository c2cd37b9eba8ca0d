// The attribute-size walk over EXR headers (see exr_header.h). Layout (OpenEXR's file layout document): magic
// 76 2f 31 01, a 4-byte version word (bit 0x1000: multi-part), then per part a header of attributes
// `name\0 type\0 int32 size, size bytes`, ended by an empty name; a multi-part file ends its headers with one
// more empty name.
#include "scenes/io/exr_header.h"

#include <cstdint>
#include <fstream>
#include <map>
#include <string>

#include <OpenEXR/ImfHeader.h>

#include "scenes/io/io_error.h"
#include "raster/simd/isa.h"

namespace scenes::io {
SHADOWLAB_ISA_BEGIN

namespace {

// A NUL-terminated name of at most 255 characters (long names); false at the end of the file or when longer.
bool read_name(std::istream& in, std::string& name) {
  name.clear();
  for (char c; in.get(c);) {
    if (c == '\0') return true;
    if (name.size() == 255) return false;
    name += c;
  }
  return false;
}

bool read_u32(std::istream& in, uint32_t& v) {
  unsigned char b[4];
  if (!in.read(reinterpret_cast<char*>(b), 4)) return false;
  v = uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
  return true;
}

// The bytes OpenEXR 3.1 reads for a value of a known fixed-size type, whatever the size field says (its
// typed attributes read their own layout and do not skip to the declared end), or 0 for the others.
int64_t fixed_size(const std::string& type) {
  static const std::map<std::string, int64_t> sizes = {
      {"box2i", 16},   {"box2f", 16},          {"int", 4},          {"float", 4},    {"double", 8},
      {"v2i", 8},      {"v2f", 8},             {"v2d", 16},         {"v3i", 12},     {"v3f", 12},
      {"v3d", 24},     {"m33f", 36},           {"m33d", 72},        {"m44f", 64},    {"m44d", 128},
      {"compression", 1}, {"lineOrder", 1},    {"envmap", 1},       {"deepImageState", 1},
      {"chromaticities", 32}, {"keycode", 28}, {"timecode", 8},     {"rational", 8}, {"tiledesc", 9}};
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

}  // namespace

void check_exr_header(const std::filesystem::path& path) {
  // What OpenEXR checks itself when told: no image or tile beyond the size any reader here accepts
  // (cli/image_input.cpp, read_exr_map), so a data window of 2^31 lines never sizes a line-offset table.
  static const bool limits = [] {
    Imf::Header::setMaxImageSize(65536, 65536);
    Imf::Header::setMaxTileSize(65536, 65536);
    return true;
  }();
  (void)limits;

  std::ifstream in(path, std::ios::binary);
  if (!in) return;
  in.seekg(0, std::ios::end);
  const int64_t file_size = int64_t(in.tellg());
  in.seekg(0);
  unsigned char start[8];
  if (!in.read(reinterpret_cast<char*>(start), 8)) return;
  if (start[0] != 0x76 || start[1] != 0x2f || start[2] != 0x31 || start[3] != 0x01) return;
  const bool multipart = (start[5] & 0x10) != 0;  // version word, little-endian: 0x1000 is bit 4 of byte 1

  auto refuse = [&](const std::string& name, const std::string& type, int64_t size, int64_t left) {
    throw IoError(path, "header attribute '" + name + "' (" + type + ") declares " + std::to_string(size) +
                            " bytes, more than the " + std::to_string(left) + " left in the file");
  };
  std::string name, type, channel;
  for (int part = 0;; ++part) {
    for (int attribute = 0;; ++attribute) {
      if (!read_name(in, name)) return;
      if (name.empty()) {
        if (attribute == 0 && part > 0) return;  // a multi-part file's closing empty header
        break;
      }
      if (!read_name(in, type)) return;
      uint32_t field;
      if (!read_u32(in, field)) return;
      const int64_t size = int32_t(field);
      const int64_t left = file_size - int64_t(in.tellg());
      if (size < 0 || size > left) refuse(name, type, size, left);
      // Move on as OpenEXR does, which is not always by `size`.
      if (const int64_t fixed = fixed_size(type)) {
        in.seekg(fixed, std::ios::cur);
      } else if (type == "chlist") {  // name\0 and 16 bytes per channel, up to an empty name
        while (read_name(in, channel) && !channel.empty()) in.seekg(16, std::ios::cur);
      } else if (type == "preview") {  // width, height, then 4 bytes per pixel, allocated at once
        uint32_t w, h;
        if (!read_u32(in, w) || !read_u32(in, h)) return;
        // w · h fits 64 bits unsigned ((2³² − 1)² < 2⁶⁴); 4 bytes a pixel may not, so compare pixels first.
        const uint64_t pixels = uint64_t(w) * uint64_t(h);
        const int64_t rest = file_size - int64_t(in.tellg());
        if (rest < 0 || pixels > uint64_t(rest) / 4) {
          if (pixels <= uint64_t(INT64_MAX - 8) / 4) refuse(name, type, 8 + 4 * int64_t(pixels), left);
          throw IoError(path, "header attribute '" + name + "' (" + type + ") declares a " + std::to_string(w) +
                                  " x " + std::to_string(h) + " preview, more than the " + std::to_string(left) +
                                  " bytes left in the file");
        }
        in.seekg(int64_t(pixels) * 4, std::ios::cur);
      } else {  // string, stringvector, floatvector, idmanifest, bytes and unknown types: `size` bytes
        in.seekg(size, std::ios::cur);
      }
      if (!in) return;
    }
    if (!multipart) return;
  }
}

SHADOWLAB_ISA_END
}  // namespace scenes::io
