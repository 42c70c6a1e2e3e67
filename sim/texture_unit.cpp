#include "sim/texture_unit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "util/check.h"

namespace skinsim::sim {

using filtering::footprint_rho2;

void ExecTexUnit::unbound(int binding, const char* kind) {
  throw std::logic_error(std::string("shader sampled unbound ") + kind + " slot " +
                         std::to_string(binding));
}

const TextureCube& ExecTexUnit::cube(int binding) const {
  SKINSIM_DCHECK_INDEX(binding, kMaxTextureBindings);
  const TextureCube* t = bindings_ ? bindings_->cubes[binding] : nullptr;
  if (!t) unbound(binding, "cube");
  return *t;
}

glm::vec4 ExecTexUnit::sample_cube(int binding, const Varying<3>& direction) {
  const TextureCube& c = cube(binding);
  const CubeCoord cc = cube_coord(direction.value);
  // Footprint: the angular change of the direction across a pixel, in face texels (a face
  // spans 2 units at distance 1 from the centre).
  const float len = std::max(glm::length(direction.value), 1e-6f);
  const float scale = 0.5f * static_cast<float>(c.size()) / len;
  const float dx = glm::length(direction.ddx) * scale, dy = glm::length(direction.ddy) * scale;
  return filtered(c.face(cc.face), binding * kBindingAddressStride + c.face_offset(cc.face), cc.uv,
                  LodInput::from_rho2(footprint_rho2(dx, 0.0f, dy, 0.0f)), false);
}

glm::vec4 ExecTexUnit::sample_cube_lod(int binding, const glm::vec3& direction, float lod) {
  const TextureCube& c = cube(binding);
  const CubeCoord cc = cube_coord(direction);
  return filtered(c.face(cc.face), binding * kBindingAddressStride + c.face_offset(cc.face), cc.uv,
                  LodInput::explicit_lod(lod), true);
}

}  // namespace skinsim::sim
