#include "pipeline/lighting.h"

#include <cmath>
#include <optional>

#include "pipeline/gpu_scene.h"
#include "scene/studio_lighting.h"

namespace skinsim::pipeline {

namespace {

// The character's frame: front (towards the scene's camera, horizontal), right and up.
struct CharacterFrame {
  glm::vec3 centre, front, right, up;
};

CharacterFrame character_frame(const GpuScene& gs) {
  const scene::Camera& cam = gs.scene().camera;
  CharacterFrame f;
  const Bounds b = gs.has_skin() ? gs.skin_bounds() : gs.bounds();
  // A scan's measured head, so that a bust orbits its face and not its chest.
  const std::optional<scene::HeadLandmarks>& head = gs.scene().head;
  f.centre = head ? head->centre() : b.centre();
  f.up = glm::normalize(cam.up);
  glm::vec3 to_camera = cam.position - f.centre;
  to_camera -= f.up * glm::dot(to_camera, f.up);
  if (glm::length(to_camera) < 1e-6f) to_camera = cam.position - cam.target;  // camera overhead
  to_camera -= f.up * glm::dot(to_camera, f.up);
  f.front = glm::length(to_camera) > 1e-6f ? glm::normalize(to_camera) : glm::vec3(0, 0, 1);
  f.right = glm::normalize(glm::cross(f.up, f.front));
  return f;
}

}  // namespace

glm::vec3 direction_from_angles(float azimuth_deg, float elevation_deg, const glm::vec3& front,
                                const glm::vec3& right, const glm::vec3& up) {
  const float az = glm::radians(azimuth_deg), el = glm::radians(elevation_deg);
  return glm::normalize(std::cos(el) * (std::cos(az) * front + std::sin(az) * right) +
                        std::sin(el) * up);
}

float key_light_azimuth_deg(const GpuScene& gs) {
  const CharacterFrame f = character_frame(gs);
  const glm::vec3 d = glm::normalize(gs.scene().key_light.direction);
  return glm::degrees(std::atan2(glm::dot(d, f.right), glm::dot(d, f.front)));
}

FrameLighting frame_lighting(const GpuScene& gs, const PipelineConfig& cfg) {
  const scene::Scene& s = gs.scene();
  FrameLighting l{s.key_light, s.back_light, s.ambient};
  l.key.direction = glm::normalize(l.key.direction);
  if (cfg.light_azimuth_deg || cfg.light_elevation_deg) {
    const CharacterFrame f = character_frame(gs);
    const glm::vec3 d = l.key.direction;
    // The scene's own angles for the one that is not given.
    const float elevation = glm::degrees(std::asin(glm::clamp(glm::dot(d, f.up), -1.0f, 1.0f)));
    l.key.direction =
        direction_from_angles(cfg.light_azimuth_deg.value_or(key_light_azimuth_deg(gs)),
                              cfg.light_elevation_deg.value_or(elevation), f.front, f.right, f.up);
  }
  if (cfg.back_light) {
    l.back = scene::default_back_light(s.key_light);
    l.back.radiance *= *cfg.back_light;
  }
  l.back.direction = glm::normalize(l.back.direction);
  return l;
}

scene::Camera frame_camera(const GpuScene& gs, const PipelineConfig& cfg) {
  scene::Camera cam = gs.scene().camera;
  if (!cfg.camera_distance_m && cfg.camera_yaw_deg == 0.0f) return cam;
  const CharacterFrame f = character_frame(gs);
  glm::vec3 offset = cam.position - f.centre;
  const float distance = glm::length(offset);
  const float units_per_m = gs.scene().units_per_mm * 1000.0f;
  const float new_distance =
      cfg.camera_distance_m ? *cfg.camera_distance_m * units_per_m : distance;
  // Orbit about the up axis through the skin's centre (Rodrigues' rotation formula).
  const float yaw = glm::radians(cfg.camera_yaw_deg);
  const glm::vec3 k = f.up;
  offset = offset * std::cos(yaw) + glm::cross(k, offset) * std::sin(yaw) +
           k * glm::dot(k, offset) * (1.0f - std::cos(yaw));
  const glm::vec3 dir = distance > 0.0f ? offset / distance : f.front;
  cam.position = f.centre + dir * new_distance;
  cam.target = f.centre;
  // Keep the clip range around the subject as the distance changes.
  if (distance > 0.0f) {
    const float ratio = new_distance / distance;
    cam.znear *= ratio;
    cam.zfar *= ratio;
    if (cam.projection == scene::Projection::kOrthographic) cam.ymag *= ratio;
  }
  return cam;
}

}  // namespace skinsim::pipeline
