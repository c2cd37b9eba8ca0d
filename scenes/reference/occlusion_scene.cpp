// OcclusionScene over Embree 3 (see occlusion_scene.h): one triangle geometry, robust build, rtcOccluded1.
#include "scenes/reference/occlusion_scene.h"

#include <embree3/rtcore.h>

#include <cstring>
#include <string>
#include <vector>
#include "raster/simd/isa.h"

namespace reference {
SHADOWLAB_ISA_BEGIN

namespace {

// One masked material's triangles as the filter reads them (copies: the soup need not outlive the scene).
struct MaskedGeometry {
  std::vector<glm::vec2> texcoords;
  std::vector<uint32_t> indices;
  const shading::SurfaceTexture* surface = nullptr;
};

// Embree's occlusion filter: a hit on a masked triangle counts only where its alpha passes.
void alpha_filter(const RTCFilterFunctionNArguments* args) {
  const auto* g = static_cast<const MaskedGeometry*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const float u = RTCHitN_u(args->hit, args->N, i), v = RTCHitN_v(args->hit, args->N, i);
    const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
    const std::vector<glm::vec2>& st = g->texcoords;
    const uint32_t* tri = g->indices.data() + 3 * size_t(prim);
    // Embree's barycentrics: the hit is (1 − u − v) · v0 + u · v1 + v · v2.
    const glm::vec2 at = (1.0f - u - v) * st[tri[0]] + u * st[tri[1]] + v * st[tri[2]];
    if (g->surface->discarded_at(at)) args->valid[i] = 0;
  }
}

}  // namespace

struct OcclusionScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<MaskedGeometry> masked;  // the filters' user data
  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
  void check(const char* step) const {
    const RTCError e = rtcGetDeviceError(device);
    if (e != RTC_ERROR_NONE) throw ReferenceError(std::string("embree: ") + step + " failed (error " + std::to_string(int(e)) + ")");
  }
};

namespace {

// A triangle geometry over `positions` and `indices`, attached to `scene`; with `filter`, its occlusion filter
// reading `user`.
void attach_triangles(RTCDevice device, RTCScene scene, std::span<const glm::vec3> positions,
                      std::span<const uint32_t> indices, RTCFilterFunctionN filter, void* user) {
  RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(
      rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), positions.size()));
  auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                             3 * sizeof(unsigned), indices.size() / 3));
  if (!v || !idx) {
    rtcReleaseGeometry(g);
    return;  // the device error is checked by the caller
  }
  for (size_t i = 0; i < positions.size(); ++i) std::memcpy(v + 3 * i, &positions[i], 3 * sizeof(float));
  for (size_t i = 0; i < indices.size(); ++i) idx[i] = indices[i];
  if (filter) {
    rtcSetGeometryUserData(g, user);
    rtcSetGeometryOccludedFilterFunction(g, filter);
  }
  rtcCommitGeometry(g);
  rtcAttachGeometry(scene, g);
  rtcReleaseGeometry(g);
}

}  // namespace

OcclusionScene::OcclusionScene(const scenes::TriangleSoup& soup)
    : OcclusionScene(scenes::CoverageSoup{soup, {}}, {}) {}

OcclusionScene::OcclusionScene(const scenes::CoverageSoup& casters, std::span<const shading::SurfaceTexture> surfaces)
    : impl_(std::make_unique<Impl>()) {
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) throw ReferenceError("embree: cannot create a device (error " + std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
  impl_->scene = rtcNewScene(impl_->device);
  // Robust traversal: no ray slips between two triangles sharing an edge.
  rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);
  const scenes::TriangleSoup& soup = casters.opaque;
  triangles_ = soup.triangle_count();
  if (triangles_ > 0) attach_triangles(impl_->device, impl_->scene, soup.positions, soup.indices, nullptr, nullptr);
  impl_->masked.reserve(casters.masked.size());  // stable addresses: the filters keep pointers
  for (const scenes::MaskedSoup& m : casters.masked) {
    if (m.indices.empty()) continue;
    if (m.material >= surfaces.size()) throw ReferenceError("reference: no surface for a masked material");
    impl_->masked.push_back(MaskedGeometry{m.texcoords, m.indices, &surfaces[m.material]});
    attach_triangles(impl_->device, impl_->scene, m.positions, m.indices, &alpha_filter, &impl_->masked.back());
    triangles_ += m.indices.size() / 3;
  }
  impl_->check("allocating the triangle buffers");
  rtcCommitScene(impl_->scene);
  impl_->check("building the BVH");
}

OcclusionScene::~OcclusionScene() = default;

bool OcclusionScene::occluded(const glm::vec3& o, const glm::vec3& d, float t_max) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = o.x, ray.org_y = o.y, ray.org_z = o.z;
  ray.dir_x = d.x, ray.dir_y = d.y, ray.dir_z = d.z;
  ray.tnear = 0.0f;
  ray.tfar = t_max;
  ray.mask = 0xFFFFFFFFu;
  ray.flags = 0;
  ray.time = 0.0f;
  rtcOccluded1(impl_->scene, &context, &ray);
  return ray.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

SHADOWLAB_ISA_END
}  // namespace reference
