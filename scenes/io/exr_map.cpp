// OpenEXR reading and writing of shadow maps (layout and attribute names in exr_map.h).
#include "scenes/io/exr_map.h"

#include <OpenEXR/ImfBoxAttribute.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <exception>

#include <glm/gtc/type_ptr.hpp>

#include "scenes/io/atomic_write.h"
#include "scenes/io/exr_memory.h"
#include "scenes/io/exr_header.h"
#include "scenes/io/io_error.h"
#include "raster/simd/isa.h"

namespace scenes::io {
SHADOWLAB_ISA_BEGIN

namespace {

constexpr const char* kTechnique = "shadowlab:technique";
constexpr const char* kDepthFormat = "shadowlab:depthFormat";
constexpr const char* kEncoding = "shadowlab:encoding";
constexpr const char* kPassCount = "shadowlab:passCount";

std::string pass_attr(size_t i, const char* what) { return "shadowlab:pass" + std::to_string(i) + ":" + what; }

// glm::value_ptr order is M44f's memory order (CONVENTIONS): element [c][r] of glm is x[c][r] of Imath.
Imath::M44f to_imath(const glm::mat4& m) {
  Imath::M44f r;
  std::memcpy(&r.x[0][0], glm::value_ptr(m), sizeof(float) * 16);
  return r;
}
glm::mat4 to_glm(const Imath::M44f& m) { return glm::make_mat4(&m.x[0][0]); }

void check(const std::filesystem::path& path, const ExrMap& map) {
  if (map.width < 1 || map.height < 1)
    throw IoError(path, "map size " + std::to_string(map.width) + " x " + std::to_string(map.height) + " is empty");
  if (map.z.size() != size_t(map.width) * size_t(map.height))
    throw IoError(path, "map holds " + std::to_string(map.z.size()) + " depth values for " + std::to_string(map.width) +
                            " x " + std::to_string(map.height) + " texels");
  if (map.depth_format != "d16" && map.depth_format != "d24" && map.depth_format != "d32f")
    throw IoError(path, "depth format '" + map.depth_format + "' is not d16, d24 or d32f");
  for (size_t i = 0; i < map.passes.size(); ++i) {
    const raster::Rect& v = map.passes[i].viewport;
    if (v.width < 1 || v.height < 1 || v.x < 0 || v.y < 0 || v.x + v.width > map.width || v.y + v.height > map.height)
      throw IoError(path, "pass " + std::to_string(i) + " viewport lies outside the " + std::to_string(map.width) +
                              " x " + std::to_string(map.height) + " map");
  }
}

void write_file(const std::filesystem::path& file, const ExrMap& map) {
  Imf::Header header(map.width, map.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  header.channels().insert("Z", Imf::Channel(Imf::FLOAT));
  Imf::addWorldToCamera(header, to_imath(map.world_to_camera));
  Imf::addWorldToNDC(header, to_imath(map.world_to_ndc));
  header.insert(kTechnique, Imf::StringAttribute(map.technique));
  header.insert(kDepthFormat, Imf::StringAttribute(map.depth_format));
  header.insert(kEncoding, Imf::StringAttribute(map.encoding));
  header.insert(kPassCount, Imf::IntAttribute(int(map.passes.size())));
  for (size_t i = 0; i < map.passes.size(); ++i) {
    const MapPass& p = map.passes[i];
    const raster::Rect& v = p.viewport;
    header.insert(
        pass_attr(i, "viewport"),
        Imf::Box2iAttribute(Imath::Box2i(Imath::V2i(v.x, v.y), Imath::V2i(v.x + v.width - 1, v.y + v.height - 1))));
    header.insert(pass_attr(i, "worldToCamera"), Imf::M44fAttribute(to_imath(p.world_to_camera)));
    header.insert(pass_attr(i, "worldToNDC"), Imf::M44fAttribute(to_imath(p.world_to_ndc)));
    if (!p.label.empty()) header.insert(pass_attr(i, "label"), Imf::StringAttribute(p.label));
  }
  // Rows top first: file row r is GL row height − 1 − r.
  const size_t w = size_t(map.width);
  std::vector<float> top_first(map.z.size());
  for (size_t r = 0; r < size_t(map.height); ++r)
    std::copy_n(map.z.data() + (size_t(map.height) - 1 - r) * w, w, top_first.data() + r * w);
  Imf::FrameBuffer fb;
  fb.insert("Z", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(top_first.data()), sizeof(float), w * sizeof(float)));
  ExrMemoryStream bytes;  // encoded in memory, then written with every failure checked (exr_memory.h)
  {
    Imf::OutputFile out(bytes, header);
    out.setFrameBuffer(fb);
    out.writePixels(map.height);
  }  // the destructor completes the file (its line offset table)
  bytes.save(file);
}

template <class Attr>
const Attr* find(const Imf::Header& h, const std::string& name) {
  return h.findTypedAttribute<Attr>(name);
}

}  // namespace

ExrMap exr_map_from(const raster::DepthTarget& target) {
  ExrMap m;
  m.width = target.width();
  m.height = target.height();
  m.depth_format = std::string(raster::to_string(target.format()));
  m.z.resize(size_t(m.width) * size_t(m.height));
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) m.z[size_t(y) * size_t(m.width) + size_t(x)] = target.value(x, y);
  return m;
}

ExrMap exr_map_from(const raster::ColorTarget& target, int channel) {
  ExrMap m;
  m.width = target.width();
  m.height = target.height();
  m.encoding.clear();
  m.z.resize(size_t(m.width) * size_t(m.height));
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) m.z[size_t(y) * size_t(m.width) + size_t(x)] = target.read(x, y)[channel];
  return m;
}

void write_exr_map(const std::filesystem::path& path, const ExrMap& map) {
  WriteBatch batch;
  write_exr_map(batch, path, map);
  batch.commit();
}

void write_exr_map(WriteBatch& batch, const std::filesystem::path& path, const ExrMap& map) {
  check(path, map);
  batch.stage(path, [&](const std::filesystem::path& tmp) {
    try {
      write_file(tmp, map);
    } catch (const IoError&) {
      throw;  // the write's own (a full disk): stage() names the destination
    } catch (const std::exception& e) {
      throw IoError(tmp, e.what());
    }
  });
}

ExrMap read_exr_map(const std::filesystem::path& path, const std::string& channel) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw IoError(path, "no such file");
  check_exr_header(path);
  try {
    Imf::InputFile in(path.c_str());
    const Imf::Header& h = in.header();
    if (!h.channels().findChannel(channel)) throw IoError(path, "no " + channel + " channel");
    const Imath::Box2i dw = h.dataWindow();
    // The size a header claims, refused before anything is allocated for it (in 64 bits: the window may span
    // the whole int range). The bound is the one inspect and diff apply to any image (cli/image_input.cpp).
    const int64_t width = int64_t(dw.max.x) - dw.min.x + 1, height = int64_t(dw.max.y) - dw.min.y + 1;
    if (width < 1 || height < 1 || width > 65536 || height > 65536 || width * height > (int64_t(1) << 30))
      throw IoError(path, "data window " + std::to_string(width) + " x " + std::to_string(height) +
                              " is beyond what a map may hold (65536 per side, 2^30 values)");
    ExrMap m;
    m.width = int(width);
    m.height = int(height);
    m.z.resize(size_t(m.width) * size_t(m.height));
    // Read top first (OpenEXR addresses pixel (x, y) at base + x·xStride + y·yStride, so base is shifted by
    // the data window's origin), then flip into GL order.
    const size_t w = size_t(m.width);
    std::vector<float> top_first(m.z.size());
    char* base = reinterpret_cast<char*>(top_first.data()) - ptrdiff_t(dw.min.x) * ptrdiff_t(sizeof(float)) -
                 ptrdiff_t(dw.min.y) * ptrdiff_t(w * sizeof(float));
    Imf::FrameBuffer fb;
    fb.insert(channel, Imf::Slice(Imf::FLOAT, base, sizeof(float), w * sizeof(float), 1, 1, 1.0));
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);
    for (size_t r = 0; r < size_t(m.height); ++r)
      std::copy_n(top_first.data() + r * w, w, m.z.data() + (size_t(m.height) - 1 - r) * w);

    m.channel = channel;
    m.has_world_to_camera = Imf::hasWorldToCamera(h);
    m.has_world_to_ndc = Imf::hasWorldToNDC(h);
    if (m.has_world_to_camera) m.world_to_camera = to_glm(Imf::worldToCamera(h));
    if (m.has_world_to_ndc) m.world_to_ndc = to_glm(Imf::worldToNDC(h));
    if (auto* a = find<Imf::StringAttribute>(h, kTechnique)) m.technique = a->value();
    if (auto* a = find<Imf::StringAttribute>(h, kDepthFormat)) m.depth_format = a->value();
    m.encoding.clear();
    if (auto* a = find<Imf::StringAttribute>(h, kEncoding)) m.encoding = a->value();
    const auto* count = find<Imf::IntAttribute>(h, kPassCount);
    const int passes = count ? count->value() : 0;
    if (passes < 0) throw IoError(path, std::string(kPassCount) + " is negative");
    for (size_t i = 0; i < size_t(passes); ++i) {
      MapPass p;
      const auto* vp = find<Imf::Box2iAttribute>(h, pass_attr(i, "viewport"));
      const auto* wc = find<Imf::M44fAttribute>(h, pass_attr(i, "worldToCamera"));
      const auto* wn = find<Imf::M44fAttribute>(h, pass_attr(i, "worldToNDC"));
      if (!vp) throw IoError(path, pass_attr(i, "viewport") + " is missing");
      if (!wc) throw IoError(path, pass_attr(i, "worldToCamera") + " is missing");
      if (!wn) throw IoError(path, pass_attr(i, "worldToNDC") + " is missing");
      const Imath::Box2i& b = vp->value();
      // In 64 bits: a box from another writer may span the whole int range (issue 23: -2^31 overflowed).
      const int64_t x0 = b.min.x, y0 = b.min.y, x1 = b.max.x, y1 = b.max.y;
      if (x0 < 0 || y0 < 0 || x1 < x0 || y1 < y0 || x1 >= m.width || y1 >= m.height)
        throw IoError(path, pass_attr(i, "viewport") + " lies outside the " + std::to_string(m.width) + " x " +
                                std::to_string(m.height) + " map");
      p.viewport = raster::Rect{int(x0), int(y0), int(x1 - x0 + 1), int(y1 - y0 + 1)};
      p.world_to_camera = to_glm(wc->value());
      p.world_to_ndc = to_glm(wn->value());
      if (auto* l = find<Imf::StringAttribute>(h, pass_attr(i, "label"))) p.label = l->value();
      m.passes.push_back(std::move(p));
    }
    return m;
  } catch (const IoError&) {
    throw;
  } catch (const std::exception& e) {
    throw IoError(path, e.what());
  }
}

std::vector<std::string> exr_channel_names(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw IoError(path, "no such file");
  check_exr_header(path);
  try {
    Imf::InputFile in(path.c_str());
    std::vector<std::string> names;
    for (auto c = in.header().channels().begin(); c != in.header().channels().end(); ++c) names.emplace_back(c.name());
    return names;
  } catch (const std::exception& e) {
    throw IoError(path, e.what());
  }
}

SHADOWLAB_ISA_END
}  // namespace scenes::io
