// Tangent-space normal mapping as every lit skin pass does it: the map's normal brought to
// world space by the interpolated tangent frame (MikkTSpace: bitangent = sign x cross(N, T),
// the sign in the tangent's w).
#pragma once

#include "sim/shader_io.h"

namespace skinsim::pipeline::shaders {

namespace sl = sim::sl;

// `vertex_normal` must be normalised; `normal_map` is the RGBA sample (xyz in [0,1]).
template <class L>
typename L::vec3 normal_mapped(const typename L::vec3& vertex_normal,
                               const typename L::vec4& tangent4,
                               const typename L::vec4& normal_map) {
  using vec3 = typename L::vec3;
  const vec3 tangent = sl::xyz(tangent4);
  const vec3 bitangent = sl::cross(vertex_normal, tangent) * sl::w(tangent4);
  const vec3 nt = sl::xyz(normal_map) * 2.0f - 1.0f;
  return sl::normalize(tangent * sl::x(nt) + bitangent * sl::y(nt) + vertex_normal * sl::z(nt));
}

}  // namespace skinsim::pipeline::shaders
