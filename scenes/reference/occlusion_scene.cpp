// OcclusionScene over Embree 3 (see occlusion_scene.h): one triangle geometry, robust build, rtcOccluded1.
#include "scenes/reference/occlusion_scene.h"

#include <embree3/rtcore.h>

#include <cstring>
#include <string>

namespace reference {

struct OcclusionScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
  void check(const char* step) const {
    const RTCError e = rtcGetDeviceError(device);
    if (e != RTC_ERROR_NONE) throw ReferenceError(std::string("embree: ") + step + " failed (error " + std::to_string(int(e)) + ")");
  }
};

OcclusionScene::OcclusionScene(const scenes::TriangleSoup& soup) : impl_(std::make_unique<Impl>()) {
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) throw ReferenceError("embree: cannot create a device (error " + std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
  impl_->scene = rtcNewScene(impl_->device);
  // Robust traversal: no ray slips between two triangles sharing an edge.
  rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);
  triangles_ = soup.triangle_count();
  if (triangles_ > 0) {
    RTCGeometry g = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), soup.positions.size()));
    auto* idx = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles_));
    impl_->check("allocating the triangle buffers");
    for (size_t i = 0; i < soup.positions.size(); ++i) std::memcpy(v + 3 * i, &soup.positions[i], 3 * sizeof(float));
    for (size_t i = 0; i < soup.indices.size(); ++i) idx[i] = soup.indices[i];
    rtcCommitGeometry(g);
    rtcAttachGeometry(impl_->scene, g);
    rtcReleaseGeometry(g);
  }
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

}  // namespace reference
