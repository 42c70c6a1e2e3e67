#include "scene/studio_lighting.h"

#include <cmath>

#include "scene/error.h"

namespace skinsim::scene {
namespace {

float smoothstep(float e0, float e1, float x) {
  const float t = glm::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// A rectangular softbox centred on direction `axis`, half-extents in radians-ish tangent
// units, soft edges; returns 0..1 coverage.
float softbox(const glm::vec3& dir, const glm::vec3& axis, float half_w, float half_h) {
  const float c = glm::dot(dir, axis);
  if (c <= 0.0f) return 0.0f;
  const glm::vec3 right = glm::normalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), axis));
  const glm::vec3 up = glm::cross(axis, right);
  const float x = glm::dot(dir, right) / c;  // gnomonic projection onto the box plane
  const float y = glm::dot(dir, up) / c;
  const float edge = 0.04f;
  return (1.0f - smoothstep(half_w - edge, half_w + edge, std::abs(x))) *
         (1.0f - smoothstep(half_h - edge, half_h + edge, std::abs(y)));
}

glm::vec3 studio_radiance(const glm::vec3& dir, const glm::vec3& key_axis,
                          const glm::vec3& rim_axis) {
  // Walls: warm grey, brighter above the horizon; floor darker.
  const float up = dir.y;
  const glm::vec3 ceiling(0.32f, 0.31f, 0.30f);
  const glm::vec3 horizon(0.18f, 0.17f, 0.16f);
  const glm::vec3 floor(0.05f, 0.045f, 0.04f);
  glm::vec3 c = up >= 0.0f ? glm::mix(horizon, ceiling, std::sqrt(up))
                           : glm::mix(horizon, floor, std::sqrt(-up));
  // HDR softboxes: the key box is ~20x brighter than the walls, the rim box ~8x.
  c += glm::vec3(6.0f, 5.8f, 5.5f) * softbox(dir, key_axis, 0.35f, 0.45f);
  c += glm::vec3(2.2f, 2.3f, 2.5f) * softbox(dir, rim_axis, 0.15f, 0.5f);
  return c;
}

}  // namespace

glm::vec3 rim_axis(const DirectionalLight& key) {
  const glm::vec3 key_axis = glm::normalize(key.direction);
  return glm::normalize(glm::vec3(-key_axis.x, 0.25f, -0.8f));
}

DirectionalLight default_back_light(const DirectionalLight& key) {
  DirectionalLight l;
  l.direction = rim_axis(key);
  // Cool, a little under the key: a rim light that lights the ears from behind.
  l.radiance = glm::vec3(0.75f, 0.8f, 0.9f);
  return l;
}

DirectionalLight default_key_light() {
  DirectionalLight l;
  l.direction = glm::normalize(glm::vec3(-0.45f, 0.55f, 0.7f));
  l.radiance = glm::vec3(1.0f, 0.97f, 0.92f);
  return l;
}

glm::vec3 default_ambient() {
  return glm::vec3(0.08f, 0.08f, 0.085f);
}

glm::vec3 cube_face_direction(int face, float s, float t) {
  switch (face) {
    case 0:
      return {1.0f, -t, -s};
    case 1:
      return {-1.0f, -t, s};
    case 2:
      return {s, 1.0f, t};
    case 3:
      return {s, -1.0f, -t};
    case 4:
      return {s, -t, 1.0f};
    default:
      return {-s, -t, -1.0f};
  }
}

CubeMap make_studio_environment(int face_size, const DirectionalLight& key) {
  if (face_size < 1 || face_size > 4096) {
    throw SceneError("environment_size must be in [1, 4096], got " + std::to_string(face_size));
  }
  const glm::vec3 key_axis = glm::normalize(key.direction);
  const glm::vec3 rim = rim_axis(key);
  CubeMap cube;
  cube.size = face_size;
  for (int f = 0; f < 6; ++f) {
    auto& texels = cube.faces[f];
    texels.resize(static_cast<std::size_t>(face_size) * face_size);
    for (int y = 0; y < face_size; ++y) {
      for (int x = 0; x < face_size; ++x) {
        const float s = 2.0f * (x + 0.5f) / face_size - 1.0f;
        const float t = 2.0f * (y + 0.5f) / face_size - 1.0f;
        const glm::vec3 dir = glm::normalize(cube_face_direction(f, s, t));
        texels[static_cast<std::size_t>(y) * face_size + x] =
            glm::vec4(studio_radiance(dir, key_axis, rim), 1.0f);
      }
    }
  }
  return cube;
}

}  // namespace skinsim::scene
