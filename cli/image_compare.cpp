// Image comparison shared by `diff` and `check` (see image_compare.h).
#include "cli/image_compare.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <OpenImageIO/imagebufalgo.h>

#include "cli/cli_common.h"
#include "cli/image_input.h"
#include "cli/json_output.h"
#include "raster/target.h"
#include "scenes/io/exr_map.h"
#include "scenes/io/png_frame.h"
#include "raster/simd/isa.h"

namespace cli {
SHADOWLAB_ISA_BEGIN
namespace {

// A map's chosen channel as a one-channel float image, top row first (the files' order).
OIIO::ImageBuf map_image(const scenes::io::ExrMap& m) {
  OIIO::ImageBuf img(OIIO::ImageSpec(m.width, m.height, 1, OIIO::TypeDesc::FLOAT));
  std::vector<float> top_first(m.z.size());
  const size_t w = size_t(m.width);
  for (size_t r = 0; r < size_t(m.height); ++r)
    std::copy_n(m.z.data() + (size_t(m.height) - 1 - r) * w, w, top_first.data() + r * w);
  img.set_pixels(img.roi(), OIIO::TypeDesc::FLOAT, top_first.data());
  return img;
}

void check_same_size(const std::string& a, const std::string& b, const OIIO::ImageBuf& x, const OIIO::ImageBuf& y) {
  const OIIO::ImageSpec &sa = x.spec(), &sb = y.spec();
  if (sa.width != sb.width || sa.height != sb.height)
    throw CliError(b, "size " + std::to_string(sb.width) + "x" + std::to_string(sb.height) + " differs from " + a +
                          " (" + std::to_string(sa.width) + "x" + std::to_string(sa.height) + ")");
  if (sa.nchannels != sb.nchannels)
    throw CliError(b, std::to_string(sb.nchannels) + " channels where " + a + " has " + std::to_string(sa.nchannels));
}

// The difference image: per pixel the largest absolute difference of any channel, through OpenImageIO's
// "inferno" colour map over [0, scale] (NaN differences white). An sRGB target ready for write_png.
raster::ColorTarget heat_map(const OIIO::ImageBuf& x, const OIIO::ImageBuf& y, double scale) {
  OIIO::ImageBuf d = OIIO::ImageBufAlgo::maxchan(OIIO::ImageBufAlgo::absdiff(x, y));
  const int w = d.spec().width, h = d.spec().height;
  std::vector<float> v(size_t(w) * size_t(h));
  d.get_pixels(d.roi(), OIIO::TypeDesc::FLOAT, v.data());
  std::vector<uint8_t> nan(v.size());
  for (size_t i = 0; i < v.size(); ++i) {
    nan[i] = std::isnan(v[i]);
    v[i] = nan[i] ? 0.0f : float(std::min(1.0, double(v[i]) / scale));
  }
  d.set_pixels(d.roi(), OIIO::TypeDesc::FLOAT, v.data());
  const OIIO::ImageBuf c = OIIO::ImageBufAlgo::color_map(d, 0, "inferno");
  std::vector<float> rgb(v.size() * 3);
  c.get_pixels(c.roi(), OIIO::TypeDesc::FLOAT, rgb.data());
  raster::ColorTarget out(w, h, raster::ColorFormat::rgba8, /*srgb=*/true);  // the map's values are display values
  for (int r = 0; r < h; ++r) {
    uint8_t* row = out.row8(h - 1 - r);  // file row r is target row h − 1 − r
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(r) * size_t(w) + size_t(x);
      for (int ch = 0; ch < 3; ++ch)
        row[4 * x + ch] = nan[i] ? 255 : uint8_t(std::lround(std::clamp(rgb[3 * i + size_t(ch)], 0.0f, 1.0f) * 255.0f));
      row[4 * x + 3] = 255;
    }
  }
  return out;
}

}  // namespace

nlohmann::json compare_images(const std::string& a, const std::string& b, const CompareOptions& o) {
  const ImageKind ka = image_kind(a), kb = image_kind(b);
  if (ka != kb)
    throw CliError(b, "cannot compare a " + lower_extension(b) + " file with a " + lower_extension(a) +
                               " file");
  const bool depth = ka == ImageKind::exr;
  if (!depth && !o.channel.empty()) throw CliError("--channel", "picks a depth map's channel; these are frames");

  nlohmann::json j = {{"a", a}, {"b", b}, {"kind", depth ? "depth map" : "frame"}};
  OIIO::ImageBuf x, y;
  size_t only_a = 0, only_b = 0, nan_pixels = 0;
  if (depth) {
    const ChannelChoice ca = choose_depth_channel(scenes::io::exr_channel_names(a), o.channel, a);
    const ChannelChoice cb = choose_depth_channel(scenes::io::exr_channel_names(b), o.channel, b);
    const scenes::io::ExrMap ma = scenes::io::read_exr_map(a, ca.name);
    const scenes::io::ExrMap mb = scenes::io::read_exr_map(b, cb.name);
    x = map_image(ma), y = map_image(mb);
    check_same_size(a, b, x, y);
    for (size_t i = 0; i < ma.z.size(); ++i) {  // coverage: drawn (< 1) in one map and not the other
      const bool a_cov = ma.z[i] < 1.0f, b_cov = mb.z[i] < 1.0f;
      only_a += a_cov && !b_cov;
      only_b += b_cov && !a_cov;
      nan_pixels += std::isnan(ma.z[i]) || std::isnan(mb.z[i]);
    }
    j["channels"] = {{"a", ca.name}, {"b", cb.name}};
  } else {
    x = read_image(a), y = read_image(b);
    check_same_size(a, b, x, y);
    j["channels"] = {{"a", x.spec().channelnames}, {"b", y.spec().channelnames}};
  }
  const size_t pixels = size_t(x.spec().width) * size_t(x.spec().height);
  if (!depth) {  // a NaN can only come from a float file, but the count is exact either way
    OIIO::ImageBuf d = OIIO::ImageBufAlgo::maxchan(OIIO::ImageBufAlgo::absdiff(x, y));
    nan_pixels = size_t(OIIO::ImageBufAlgo::computePixelStats(d).nancount[0]);
  }
  // OpenImageIO's metrics: mean, RMS, PSNR (peak 1) and the pixels with some channel over the threshold. A NaN
  // difference is no number to average, so it is counted apart and always over the tolerance.
  const OIIO::ImageBufAlgo::CompareResults cr =
      OIIO::ImageBufAlgo::compare(x, y, float(o.tolerance), float(o.tolerance));
  // (cr.error only says that some pixel failed the threshold: nfail > 0.)
  const size_t over = size_t(cr.nfail) + nan_pixels;
  const double share = pixels ? 100.0 * double(over) / double(pixels) : 0.0;
  const double max = nan_pixels ? INFINITY : cr.maxerror;

  j["width"] = x.spec().width, j["height"] = x.spec().height, j["pixels"] = pixels;
  j["max"] = json_number(max);
  j["max_at"] = cr.maxerror > 0 ? nlohmann::json({cr.maxx, cr.maxy}) : nlohmann::json(nullptr);
  j["mean"] = cr.meanerror, j["rmse"] = cr.rms_error;
  j["psnr"] = json_number(cr.PSNR);  // infinite (null) for identical images
  j["nan_pixels"] = nan_pixels;
  j["tolerance"] = o.tolerance;
  j["over"] = over, j["over_percent"] = share;
  if (depth) j["covered_only_a"] = only_a, j["covered_only_b"] = only_b;
  j["diff_out"] = nullptr;
  if (!o.diff_out.empty()) {
    // Scaled to the largest finite difference, or to the tolerance when that is larger (so a pass stays dark).
    const double scale = std::max({cr.maxerror, o.tolerance, 1e-30});
    scenes::io::write_png(o.diff_out, heat_map(x, y, scale));
    j["diff_out"] = {{"file", o.diff_out}, {"colour_map", "inferno"}, {"range", {0.0, scale}}};
  }

  return j;
}

bool over_limit(const nlohmann::json& result, const FailOver& limit) {
  return limit.percent ? result.at("over_percent").get<double>() > limit.value
                       : double(result.at("over").get<size_t>()) > limit.value;
}

FailOver parse_fail_over(const std::string& text, const std::string& where) {
  if (text.empty()) return {};
  FailOver f;
  std::string number = text;
  if (!number.empty() && number.back() == '%') {
    f.percent = true;
    number.pop_back();
  }
  size_t used = 0;
  try {
    f.value = std::stod(number, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != number.size() || !std::isfinite(f.value) || f.value < 0 ||
      (f.percent && f.value > 100) || (!f.percent && f.value != std::floor(f.value)))
    throw CliError(where, "expected a pixel count N >= 0 or a share P% with 0 <= P <= 100, got '" + text + "'");
  return f;
}

SHADOWLAB_ISA_END
}  // namespace cli
