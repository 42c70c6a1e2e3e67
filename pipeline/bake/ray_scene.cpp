#include "pipeline/bake/ray_scene.h"

#include <embree3/rtcore.h>

#include <array>
#include <cstring>
#include <stdexcept>
#include <string>

namespace skinsim::bake {

struct RayScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
};

namespace {

RTCRay make_ray(const glm::vec3& o, const glm::vec3& d, float t_near, float t_far) {
  RTCRay r{};
  r.org_x = o.x;
  r.org_y = o.y;
  r.org_z = o.z;
  r.dir_x = d.x;
  r.dir_y = d.y;
  r.dir_z = d.z;
  r.tnear = t_near;
  r.tfar = t_far;
  r.mask = 0xFFFFFFFFu;
  r.flags = 0;
  return r;
}

// The nearest hit along `ray`: geomID is RTC_INVALID_GEOMETRY_ID when there is none.
RTCRayHit intersect(RTCScene scene, const RTCRay& ray) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit hit{};
  hit.ray = ray;
  hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &context, &hit);
  return hit;
}

}  // namespace

RayScene::RayScene(const std::vector<RayMesh>& meshes) : impl_(std::make_unique<Impl>()) {
  // Default threading: Embree builds with TBB. (A "threads=N" setting would cap the whole
  // process's TBB parallelism while the device lives.) The hits do not depend on how the
  // BVH was built: a ray's nearest distance and whether it is blocked are properties of the
  // triangles.
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) {
    throw std::runtime_error("Embree: cannot create a device (error " +
                             std::to_string(rtcGetDeviceError(nullptr)) + ")");
  }
  impl_->scene = rtcNewScene(impl_->device);
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);
  rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST);
  for (std::size_t mesh = 0; mesh < meshes.size(); ++mesh) {
    const RayMesh& m = meshes[mesh];
    const std::size_t triangles = m.indices->size() / 3;
    if (triangles == 0 || m.positions->empty()) continue;
    RTCGeometry g = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(float) * 3, m.positions->size()));
    std::memcpy(v, m.positions->data(), m.positions->size() * sizeof(glm::vec3));
    auto* idx = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, sizeof(std::uint32_t) * 3, triangles));
    std::memcpy(idx, m.indices->data(), triangles * 3 * sizeof(std::uint32_t));
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(impl_->scene, g, static_cast<unsigned>(mesh));  // hits name the mesh
    rtcReleaseGeometry(g);
  }
  rtcCommitScene(impl_->scene);
}

RayScene::~RayScene() {
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

float RayScene::closest_hit(const glm::vec3& origin, const glm::vec3& direction, float t_near,
                            float t_far) const {
  const RTCRayHit hit = intersect(impl_->scene, make_ray(origin, direction, t_near, t_far));
  return hit.hit.geomID == RTC_INVALID_GEOMETRY_ID ? std::numeric_limits<float>::infinity()
                                                   : hit.ray.tfar;
}

std::optional<TriangleHit> RayScene::nearest_triangle(const glm::vec3& origin,
                                                      const glm::vec3& direction, float t_near,
                                                      float t_far) const {
  const RTCRayHit hit = intersect(impl_->scene, make_ray(origin, direction, t_near, t_far));
  if (hit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  // Embree's u and v weigh the triangle's second and third vertices.
  return TriangleHit{hit.hit.geomID, hit.hit.primID,
                     glm::vec3(1.0f - hit.hit.u - hit.hit.v, hit.hit.u, hit.hit.v)};
}

bool RayScene::occluded(const glm::vec3& origin, const glm::vec3& direction, float t_near,
                        float t_far) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = make_ray(origin, direction, t_near, t_far);
  rtcOccluded1(impl_->scene, &context, &ray);
  return ray.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

int RayScene::unoccluded(const glm::vec3& origin, std::span<const glm::vec3> directions,
                         float t_near, float t_far, std::span<bool> open_rays) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // one origin, nearby directions
  constexpr int kPacket = 16;
  int open = 0;
  for (std::size_t first = 0; first < directions.size(); first += kPacket) {
    alignas(64) std::array<int, kPacket> valid{};
    RTCRay16 rays{};
    for (int i = 0; i < kPacket; ++i) {
      const std::size_t k = first + i;
      valid[i] = k < directions.size() ? -1 : 0;
      const glm::vec3 d = k < directions.size() ? directions[k] : glm::vec3(0.0f, 0.0f, 1.0f);
      rays.org_x[i] = origin.x;
      rays.org_y[i] = origin.y;
      rays.org_z[i] = origin.z;
      rays.dir_x[i] = d.x;
      rays.dir_y[i] = d.y;
      rays.dir_z[i] = d.z;
      rays.tnear[i] = t_near;
      rays.tfar[i] = t_far;
      rays.mask[i] = 0xFFFFFFFFu;
    }
    rtcOccluded16(valid.data(), impl_->scene, &context, &rays);
    for (int i = 0; i < kPacket; ++i) {
      if (!valid[i]) continue;
      const bool is_open = rays.tfar[i] >= 0.0f;  // Embree sets tfar to -inf on a hit
      if (!open_rays.empty()) open_rays[first + i] = is_open;
      open += is_open ? 1 : 0;
    }
  }
  return open;
}

}  // namespace skinsim::bake
