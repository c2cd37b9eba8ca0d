// Channel choice and image reading for inspect, diff and check (see image_input.h).
#include "cli/image_input.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include "cli/cli_common.h"
#include "scenes/io/exr_header.h"
#include "scenes/io/quiet_stderr.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN

ImageKind image_kind(const std::string& file) {
  const std::string e = lower_extension(file);
  if (e != ".exr" && e != ".png") throw CliError(file, "expected an .exr depth map or a .png frame");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) throw CliError(file, "no such file");
  return e == ".exr" ? ImageKind::exr : ImageKind::png;
}

ChannelChoice choose_depth_channel(const std::vector<std::string>& channels, const std::string& requested,
                                   const std::string& file) {
  auto has = [&](const std::string& n) { return std::find(channels.begin(), channels.end(), n) != channels.end(); };
  std::string list;
  for (const std::string& c : channels) list += (list.empty() ? "" : ", ") + c;
  if (!requested.empty()) {
    if (!has(requested)) throw CliError(file, "has no channel '" + requested + "' (channels: " + list + ")");
    return {requested, "asked for"};
  }
  if (channels.size() == 1) return {channels[0], "the only channel"};
  if (has("Z")) return {"Z", "named Z"};
  for (const std::string& c : channels)
    if (c.size() > 2 && c.compare(c.size() - 2, 2, ".Z") == 0) return {c, "a depth layer's Z"};
  if (has("R")) return {"R", "red, the first colour channel"};
  if (has("Y")) return {"Y", "luminance"};
  throw CliError(file, "no depth channel among " + list + " (choose one with --channel)");
}

OIIO::ImageBuf read_image(const std::string& file, int* file_bits) {
  const ImageKind kind = image_kind(file);
  scenes::io::check_exr_header(file);  // an attribute claiming gigabytes, before OpenEXR allocates them
  const scenes::io::QuietStderr quiet;  // libpng's own line on a broken file; ours follows
  // The reader of the format the extension names, and only that one: OpenImageIO's open-by-name tries every
  // plugin it has on a file its own reader refuses (LibRaw among them, which allocates and clears tens of
  // megabytes to say no), and a file that is not the PNG or EXR its name says is an error here, not a guess.
  // Reading through ImageInput also keeps OpenImageIO's shared ImageCache, which remembers headers by file
  // name, out of a command that may read a file rewritten since.
  auto in = OIIO::ImageInput::create(kind == ImageKind::exr ? "openexr" : "png");
  if (!in) throw CliError(file, "cannot read the image: " + OIIO::geterror());
  OIIO::ImageSpec opened;
  if (!in->open(file, opened)) {
    std::string why = in->geterror();
    if (why.empty()) why = std::string("not a readable ") + (kind == ImageKind::exr ? "EXR" : "PNG") + " file";
    throw CliError(file, why);
  }
  // The header first: a file that claims an absurd size is refused before anything is allocated.
  const OIIO::ImageSpec spec = in->spec();
  if (file_bits) *file_bits = int(spec.format.size() * 8);  // the stored samples, before the conversion below
  if (spec.width < 1 || spec.height < 1 || spec.width > 65536 || spec.height > 65536 || spec.nchannels < 1 ||
      uint64_t(spec.width) * uint64_t(spec.height) * uint64_t(spec.nchannels) > (uint64_t(1) << 30))
    throw CliError(file, "image size " + std::to_string(spec.width) + " x " + std::to_string(spec.height) + " x " +
                             std::to_string(spec.nchannels) + " channels is beyond what inspect and diff read");
  OIIO::ImageSpec float_spec = spec;
  float_spec.set_format(OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf buf(float_spec);
  // In the file's own sample types (packed, per channel), then converted here: asked for any other type,
  // OpenImageIO converts through a scratch buffer of 64 MiB whatever the image's size (a 16 x 16 map included),
  // which was most of the time a small read took.
  float* pixels = static_cast<float*>(buf.localpixels());
  const bool already_float = spec.channelformats.empty() && spec.format == OIIO::TypeDesc::FLOAT;
  const size_t values = size_t(spec.image_pixels()) * size_t(spec.nchannels);
  std::vector<std::byte> raw(already_float ? 0 : size_t(spec.image_pixels()) * spec.pixel_bytes(true));
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UNKNOWN,
                      already_float ? static_cast<void*>(pixels) : static_cast<void*>(raw.data()))) {
    std::string why = in->geterror();
    if (why.empty()) why = "cannot be read";
    throw CliError(file, why);
  }
  bool converted = true;
  if (already_float) {
  } else if (spec.channelformats.empty() && (spec.format == OIIO::TypeDesc::UINT8 || spec.format == OIIO::TypeDesc::UINT16)) {
    // Integer samples as one correctly rounded division each, code / (2^bits − 1): so a byte x and the 16-bit
    // 257 x that stores the same value read as the same float (OpenImageIO's conversion left them an ulp apart,
    // and diff failed an 8-bit frame against its 16-bit copy).
    if (spec.format == OIIO::TypeDesc::UINT8)
      for (size_t i = 0; i < values; ++i) pixels[i] = float(std::to_integer<uint8_t>(raw[i])) / 255.0f;
    else
      for (size_t i = 0; i < values; ++i) {
        uint16_t v;
        std::memcpy(&v, raw.data() + 2 * i, 2);
        pixels[i] = float(v) / 65535.0f;
      }
  } else if (spec.channelformats.empty()) {
    converted = OIIO::convert_pixel_values(spec.format, raw.data(), OIIO::TypeDesc::FLOAT, pixels, int(values));
  } else {
    const auto pixel_bytes = OIIO::stride_t(spec.pixel_bytes(true));
    size_t offset = 0;
    for (int c = 0; converted && c < spec.nchannels; ++c) {
      const OIIO::TypeDesc type = spec.channelformats[size_t(c)];
      converted = OIIO::convert_image(1, spec.width, spec.height * std::max(spec.depth, 1), 1, raw.data() + offset,
                                      type, pixel_bytes, OIIO::AutoStride, OIIO::AutoStride, pixels + c,
                                      OIIO::TypeDesc::FLOAT, OIIO::stride_t(sizeof(float)) * spec.nchannels,
                                      OIIO::AutoStride, OIIO::AutoStride);
      offset += type.size();
    }
  }
  if (!converted) throw CliError(file, "its samples cannot be converted to float");
  return buf;
}

SHADOWLAB_ISA_END
}  // namespace cli
