// The vertex shader shared by the lit surface passes (skin, eyes, background): world
// position, normal, tangent and UV as varyings; positions are already in world space.
#pragma once

#include <glm/glm.hpp>

#include "sim/shader_io.h"

namespace skinsim::pipeline::shaders {

namespace sl = sim::sl;

// Varying slots written by SurfaceVS.
struct SurfaceSlots {
  static constexpr int kWorldPos = 0;
  static constexpr int kNormal = 3;
  static constexpr int kTangent = 6;  // xyz + bitangent sign
  static constexpr int kUv = 10;
};

struct SurfaceVS {
  static constexpr const char* kName = "surface_vs";
  struct Uniforms {
    glm::mat4 view_proj{1.0f};
    float normal_offset = 0.0f;  // world units to push along the normal (irradiance pass)
  };
  template <class L>
  static void vertex(const typename L::VertexIn& in, typename L::VertexOut& out,
                     const Uniforms& u) {
    using vec4 = typename L::vec4;
    const auto n = in.normal();
    const auto p = in.position() + n * u.normal_offset;
    out.position = u.view_proj * vec4(p, 1.0f);
    out.set(SurfaceSlots::kWorldPos, p);
    out.set(SurfaceSlots::kNormal, n);
    out.set(SurfaceSlots::kTangent, in.tangent());
    out.set(SurfaceSlots::kUv, in.uv());
  }
};

// Position-and-normal-only variant (the irradiance pass needs no UV or tangent).
struct PositionNormalVS {
  static constexpr const char* kName = "position_normal_vs";
  using Uniforms = SurfaceVS::Uniforms;
  template <class L>
  static void vertex(const typename L::VertexIn& in, typename L::VertexOut& out,
                     const Uniforms& u) {
    using vec4 = typename L::vec4;
    const auto n = in.normal();
    const auto p = in.position() + n * u.normal_offset;
    out.position = u.view_proj * vec4(p, 1.0f);
    out.set(0, n);
  }
};

}  // namespace skinsim::pipeline::shaders
