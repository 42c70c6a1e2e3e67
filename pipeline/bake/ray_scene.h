// Ray casting against triangle meshes with Embree (the library the brief names for it): the
// reference renderer's shadow and ambient rays, and the thickness and occlusion bakes.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace skinsim::bake {

// Triangle lists in world space (positions and 3 indices per triangle).
struct RayMesh {
  const std::vector<glm::vec3>* positions = nullptr;
  const std::vector<std::uint32_t>* indices = nullptr;
};

// Where a ray first meets a triangle: which one, and its vertices' barycentric weights there.
struct TriangleHit {
  std::uint32_t mesh = 0;      // index into the meshes the scene was made of
  std::uint32_t triangle = 0;  // index of the triangle in that mesh (its indices at 3 * triangle)
  glm::vec3 barycentric{1.0f, 0.0f, 0.0f};
};

class RayScene {
 public:
  explicit RayScene(const std::vector<RayMesh>& meshes);
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  // Distance along `direction` (unit) to the nearest triangle in (t_near, t_far), or
  // +infinity when there is none. Thread-safe.
  float closest_hit(const glm::vec3& origin, const glm::vec3& direction, float t_near,
                    float t_far = std::numeric_limits<float>::infinity()) const;
  // The nearest triangle along `direction` (unit) in (t_near, t_far), if any. Thread-safe.
  std::optional<TriangleHit> nearest_triangle(
      const glm::vec3& origin, const glm::vec3& direction, float t_near,
      float t_far = std::numeric_limits<float>::infinity()) const;
  // Whether any triangle lies along the ray within (t_near, t_far). Thread-safe.
  bool occluded(const glm::vec3& origin, const glm::vec3& direction, float t_near,
                float t_far = std::numeric_limits<float>::infinity()) const;
  // How many of the rays from `origin` along `directions` (unit) no triangle blocks within
  // (t_near, t_far): the rays of a shadow or occlusion estimate, traced together as coherent
  // packets. Each ray's answer is occluded()'s; when `open` is given (one per direction) it
  // receives them: true where the ray is not blocked. Thread-safe.
  int unoccluded(const glm::vec3& origin, std::span<const glm::vec3> directions, float t_near,
                 float t_far = std::numeric_limits<float>::infinity(),
                 std::span<bool> open = {}) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace skinsim::bake
