// What the camera pass will shade, before it runs: the per-instance draw set-up the camera pass uses, and a
// pre-pass that draws the scene with it and keeps each pixel's visible point and plane (tech::CameraSurface) for
// the techniques that work on the camera's own samples (the irregular z-buffer). Both passes draw the same
// triangles with the same state, so they cover the same pixels with the same depths and positions.
#pragma once
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "raster/renderer.h"
#include "raster/state.h"
#include "scenes/frame/camera_shader.h"
#include "scenes/scene.h"
#include "shading/surface_texture.h"
#include "shading/techniques/technique.h"
#include "raster/simd/isa.h"

namespace frame {
SHADOWLAB_ISA_BEGIN

// A mesh's vertices as the camera shader reads them (a missing normal reads as +y).
std::vector<CameraVertex> camera_vertices(const scenes::Mesh& mesh);

// The same with the mesh's texture coordinates, for textured materials (missing ones read as (0, 0)).
std::vector<TexturedCameraVertex> textured_vertices(const std::vector<CameraVertex>& plain, const scenes::Mesh& mesh);

// Instance `index`'s uniforms (model and normal matrices, material, receives_shadows) set into `u`, and the draw
// state the camera pass draws it with (back faces culled unless its material is double-sided).
raster::DrawState camera_instance(const scenes::Scene& scene, size_t index, SurfaceUniforms& u);

// The camera's visible surface at width × height: every instance drawn as the camera pass draws it, with no
// lights, recording each pixel's world position and geometric normal (surface_record.h), and the reference's
// ray-origin offset ε = 10⁻⁴ × the diagonal of the scene's bounds. Alpha-masked materials (`surfaces`, one per
// scene material) are alpha-tested as the camera pass tests them, so a leaf card's cut-out shows what lies behind.
shading::tech::CameraSurface camera_surface(const scenes::Scene& scene,
                                            std::span<const shading::SurfaceTexture> surfaces,
                                            const glm::mat4& view_proj, glm::vec3 eye, int width, int height,
                                            raster::Renderer& renderer);

SHADOWLAB_ISA_END
}  // namespace frame
