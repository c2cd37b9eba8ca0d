// Multi-channel EXR images through OpenEXR (see exr_image.h): rows flipped between GL order and the file's top-first.
#include "scenes/io/exr_image.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>

#include <algorithm>
#include <exception>
#include <set>

#include "scenes/io/atomic_write.h"
#include "scenes/io/exr_memory.h"
#include "scenes/io/io_error.h"
#include "raster/simd/isa.h"

namespace scenes::io {
SHADOWLAB_ISA_BEGIN

namespace {

// GL rows (bottom first) <-> file rows (top first): the same flip both ways.
std::vector<float> flip_rows(const std::vector<float>& v, size_t w, size_t h) {
  std::vector<float> out(v.size());
  for (size_t r = 0; r < h; ++r) std::copy_n(v.data() + (h - 1 - r) * w, w, out.data() + r * w);
  return out;
}

void check(const std::filesystem::path& path, const ExrImage& img) {
  if (img.width < 1 || img.height < 1)
    throw IoError(path, "image size " + std::to_string(img.width) + " x " + std::to_string(img.height) + " is empty");
  if (img.channels.empty()) throw IoError(path, "no channels to write");
  std::set<std::string> names;
  for (const ExrChannel& c : img.channels) {
    if (c.name.empty()) throw IoError(path, "a channel has no name");
    if (!names.insert(c.name).second) throw IoError(path, "channel " + c.name + " appears twice");
    if (c.values.size() != size_t(img.width) * size_t(img.height))
      throw IoError(path, "channel " + c.name + " holds " + std::to_string(c.values.size()) + " values for " +
                              std::to_string(img.width) + " x " + std::to_string(img.height) + " pixels");
  }
}

}  // namespace

const ExrChannel* ExrImage::find(const std::string& name) const {
  for (const ExrChannel& c : channels)
    if (c.name == name) return &c;
  return nullptr;
}

void write_exr_image(const std::filesystem::path& path, const ExrImage& img) {
  WriteBatch batch;
  write_exr_image(batch, path, img);
  batch.commit();
}

void write_exr_image(WriteBatch& batch, const std::filesystem::path& path, const ExrImage& img) {
  check(path, img);
  const size_t w = size_t(img.width), h = size_t(img.height);
  batch.stage(path, [&](const std::filesystem::path& tmp) {
    try {
      Imf::Header header(img.width, img.height);
      header.compression() = Imf::ZIP_COMPRESSION;
      std::vector<std::vector<float>> top_first;
      for (const ExrChannel& c : img.channels) {
        header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
        top_first.push_back(flip_rows(c.values, w, h));
      }
      Imf::FrameBuffer fb;
      for (size_t i = 0; i < img.channels.size(); ++i)
        fb.insert(img.channels[i].name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(top_first[i].data()),
                                                   sizeof(float), w * sizeof(float)));
      ExrMemoryStream bytes;  // encoded in memory, then written with every failure checked (exr_memory.h)
      {
        Imf::OutputFile out(bytes, header);
        out.setFrameBuffer(fb);
        out.writePixels(img.height);
      }
      bytes.save(tmp);
    } catch (const IoError&) {
      throw;
    } catch (const std::exception& e) {
      throw IoError(tmp, e.what());
    }
  });
}

ExrImage read_exr_image(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw IoError(path, "no such file");
  try {
    Imf::InputFile in(path.c_str());
    const Imath::Box2i dw = in.header().dataWindow();
    ExrImage img;
    img.width = dw.max.x - dw.min.x + 1;
    img.height = dw.max.y - dw.min.y + 1;
    const size_t w = size_t(img.width), h = size_t(img.height);
    std::vector<std::vector<float>> top_first;
    std::vector<std::string> names;
    for (auto it = in.header().channels().begin(); it != in.header().channels().end(); ++it) {
      names.push_back(it.name());
      top_first.emplace_back(w * h);
    }
    Imf::FrameBuffer fb;
    for (size_t i = 0; i < names.size(); ++i) {
      // OpenEXR addresses pixel (x, y) at base + x·xStride + y·yStride: base is shifted by the window's origin.
      char* base = reinterpret_cast<char*>(top_first[i].data()) - ptrdiff_t(dw.min.x) * ptrdiff_t(sizeof(float)) -
                   ptrdiff_t(dw.min.y) * ptrdiff_t(w * sizeof(float));
      fb.insert(names[i], Imf::Slice(Imf::FLOAT, base, sizeof(float), w * sizeof(float), 1, 1, 0.0));
    }
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);
    for (size_t i = 0; i < names.size(); ++i) img.channels.push_back({names[i], flip_rows(top_first[i], w, h)});
    return img;
  } catch (const IoError&) {
    throw;
  } catch (const std::exception& e) {
    throw IoError(path, e.what());
  }
}

SHADOWLAB_ISA_END
}  // namespace scenes::io
