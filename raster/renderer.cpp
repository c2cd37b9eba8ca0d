// Draw validation: the checks every draw makes before any stage runs (see renderer.h).
#include "raster/renderer.h"

#include <string>
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

void Renderer::clear_tiles(DepthTarget& depth, uint32_t raw) {
  const TileGrid grid = TileGrid::for_size(depth.width(), depth.height());
  pool_.parallel_for(size_t(grid.count()), [&](size_t k) {
    const int tx = int(k % size_t(grid.tiles_x)), ty = int(k / size_t(grid.tiles_x));
    depth.fill_tile(raw, tx, ty);
  });
}

namespace detail {

void check_draw(const RenderTargets& t, const DrawState& s, size_t vertices, size_t indices) {
  if (!t.depth && !t.color) throw DrawError("draw has no render target");
  if (t.depth && t.color && (t.depth->width() != t.color->width() || t.depth->height() != t.color->height()))
    throw DrawError("depth target " + std::to_string(t.depth->width()) + "x" + std::to_string(t.depth->height()) +
                    " and colour target " + std::to_string(t.color->width()) + "x" +
                    std::to_string(t.color->height()) + " differ in size");
  if (s.viewport && (s.viewport->width <= 0 || s.viewport->height <= 0))
    throw DrawError("viewport " + std::to_string(s.viewport->width) + "x" + std::to_string(s.viewport->height) +
                    " is empty");
  if (s.scissor && (s.scissor->width < 0 || s.scissor->height < 0)) throw DrawError("scissor has a negative size");
  if (indices % 3 != 0) throw DrawError("index count " + std::to_string(indices) + " is not a multiple of 3");
  if (indices == 0 && vertices % 3 != 0)
    throw DrawError("non-indexed vertex count " + std::to_string(vertices) + " is not a multiple of 3");
}

}  // namespace detail

SHADOWLAB_ISA_END
}  // namespace raster
