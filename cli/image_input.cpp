// Channel choice and image reading for inspect, diff and check (see image_input.h).
#include "cli/image_input.h"

#include <algorithm>
#include <cstdint>

#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include "cli/cli_common.h"
#include "scenes/io/exr_header.h"
#include "scenes/io/quiet_stderr.h"

namespace cli {

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

OIIO::ImageBuf read_image(const std::string& file) {
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
  if (spec.width < 1 || spec.height < 1 || spec.width > 65536 || spec.height > 65536 || spec.nchannels < 1 ||
      uint64_t(spec.width) * uint64_t(spec.height) * uint64_t(spec.nchannels) > (uint64_t(1) << 30))
    throw CliError(file, "image size " + std::to_string(spec.width) + " x " + std::to_string(spec.height) + " x " +
                             std::to_string(spec.nchannels) + " channels is beyond what inspect and diff read");
  OIIO::ImageSpec float_spec = spec;
  float_spec.set_format(OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf buf(float_spec);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, buf.localpixels())) {
    std::string why = in->geterror();
    if (why.empty()) why = "cannot be read";
    throw CliError(file, why);
  }
  return buf;
}

}  // namespace cli
