#include "scene/camera_framing.h"

#include <algorithm>
#include <cmath>

namespace skinsim::scene {

Camera frame_front(const Bounds& bounds, float yfov_radians, float aspect, float margin) {
  const glm::vec3 c = bounds.center();
  const glm::vec3 half = 0.5f * bounds.extent();
  const float tan_y = std::tan(0.5f * yfov_radians);
  const float scale = 1.0f + margin;
  // Distance from the front face of the box at which both its height and width fit.
  const float fit = std::max(half.y / tan_y, half.x / (tan_y * aspect)) * scale;
  const float radius = std::max(glm::length(half), 1e-6f);
  Camera cam;
  cam.target = c;
  cam.position = c + glm::vec3(0.0f, 0.0f, half.z + std::max(fit, 1e-6f));
  cam.up = glm::vec3(0.0f, 1.0f, 0.0f);
  cam.yfov_radians = yfov_radians;
  const float dist = cam.position.z - c.z;
  cam.znear = std::max((dist - radius) * 0.5f, dist * 1e-3f);
  cam.zfar = dist + 2.0f * radius;
  return cam;
}

Camera frame_face(const HeadLandmarks& head, float yfov_radians, float aspect) {
  Bounds box;
  box.grow(head.box_min);
  box.grow(head.box_max);
  return frame_front(box, yfov_radians, aspect, 0.10f);
}

}  // namespace skinsim::scene
