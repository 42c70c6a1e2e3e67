// The lights and camera of one frame: the scene's, with the light and framing knobs applied
// (PipelineConfig: light_azimuth_deg, light_elevation_deg, back_light, camera_distance_m,
// camera_yaw_deg). Directions are in the character's frame: "front" is the horizontal
// direction from the subject's centre (a scan's measured head, scene::Scene::head, else the
// skin's box) towards the scene's camera, "up" the camera's up; the camera orbits that centre.
#pragma once

#include <glm/glm.hpp>

#include "pipeline/config.h"
#include "scene/scene.h"

namespace skinsim::pipeline {

class GpuScene;

struct FrameLighting {
  scene::DirectionalLight key;   // casts the shadows
  scene::DirectionalLight back;  // radiance 0: none
  glm::vec3 ambient{0.0f};
  bool has_back() const { return back.radiance != glm::vec3(0.0f); }
};

FrameLighting frame_lighting(const GpuScene& scene, const PipelineConfig& config);
// The scene's own key light azimuth in the character's frame (light_azimuth_deg's units).
float key_light_azimuth_deg(const GpuScene& scene);

scene::Camera frame_camera(const GpuScene& scene, const PipelineConfig& config);

// A direction from azimuth (about `up`, from `front` towards `right`) and elevation, degrees.
glm::vec3 direction_from_angles(float azimuth_deg, float elevation_deg, const glm::vec3& front,
                                const glm::vec3& right, const glm::vec3& up);

}  // namespace skinsim::pipeline
