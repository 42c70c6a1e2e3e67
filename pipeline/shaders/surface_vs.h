// The vertex shader shared by the lit surface passes (skin, eyes, background): world
// position, normal, tangent and UV as varyings; positions are already in world space.
#pragma once

#include <glm/glm.hpp>

#include "pipeline/shaders/lights.h"
#include "sim/shader_io.h"

namespace skinsim::pipeline::shaders {

namespace sl = sim::sl;

// Varying slots written by SurfaceVS.
struct SurfaceSlots {
  static constexpr int kWorldPos = 0;
  static constexpr int kNormal = 3;
  static constexpr int kTangent = 6;  // xyz + bitangent sign
  static constexpr int kUv = 10;
  static constexpr int kShadowCoord = 12;  // when the light needs it (lights.h)
  static constexpr int kThickness = 15;
  static constexpr LightVaryings kLight{kShadowCoord, kThickness};
};

struct SurfaceVS {
  static constexpr const char* kName = "surface_vs";
  struct Uniforms {
    glm::mat4 view_proj{1.0f};
    float normal_offset = 0.0f;  // world units to push along the normal (irradiance pass)
    LightVertexUniforms light;
    // PositionNormalVS only: write the view depth in mm, dot(p, xyz) + w, to slot kViewDepth
    // (the depth-aware mobile blur).
    bool view_depth = false;
    glm::vec4 view_depth_plane{0.0f};
  };
  // The vertex pushed `normal_offset` along its normal n, projected to out.position.
  template <class L>
  static typename L::vec3 place(const typename L::VertexIn& in, typename L::VertexOut& out,
                                const Uniforms& u, const typename L::vec3& n) {
    const typename L::vec3 p = in.position() + n * u.normal_offset;
    out.position = u.view_proj * typename L::vec4(p, 1.0f);
    return p;
  }
  template <class L>
  static void vertex(const typename L::VertexIn& in, typename L::VertexOut& out,
                     const Uniforms& u) {
    const auto n = in.normal();
    const auto p = place<L>(in, out, u, n);
    out.set(SurfaceSlots::kWorldPos, p);
    out.set(SurfaceSlots::kNormal, n);
    out.set(SurfaceSlots::kTangent, in.tangent());
    out.set(SurfaceSlots::kUv, in.uv());
    write_light_varyings<L>(in, out, u.light, p, n, SurfaceSlots::kLight);
  }
};

// Position-and-normal-only variant (the irradiance pass needs no UV or tangent): the
// normal in slot 0, then what the light needs.
struct PositionNormalVS {
  static constexpr const char* kName = "position_normal_vs";
  static constexpr LightVaryings kLight{3, 6};
  static constexpr int kViewDepth = 7;
  using Uniforms = SurfaceVS::Uniforms;
  template <class L>
  static void vertex(const typename L::VertexIn& in, typename L::VertexOut& out,
                     const Uniforms& u) {
    const auto n = in.normal();
    const auto p = SurfaceVS::place<L>(in, out, u, n);
    out.set(0, n);
    write_light_varyings<L>(in, out, u.light, p, n, kLight);
    if (u.view_depth) {
      using vec3 = typename L::vec3;
      out.set(kViewDepth, sl::dot(p, vec3(glm::vec3(u.view_depth_plane))) + u.view_depth_plane.w);
    }
  }
};

// The irradiance pass's dilation draw: PositionNormalVS (vertices pushed along the normal)
// with the depth squeezed into [kDilationDepthNear, 1) (glDepthRangef(kDilationDepthNear, 1)
// on GLES2), so the pushed copy only fills pixels no skin covers (the silhouette ring against
// the background) and never grows one skin surface over another (the nose over the upper
// lip, the jaw over the neck), which drew a cyan halo there (docs/techniques.md, mobile).
inline constexpr float kDilationDepthNear = 0.9998f;

struct DilatedPositionNormalVS {
  static constexpr const char* kName = "dilated_position_normal_vs";
  using Uniforms = SurfaceVS::Uniforms;
  template <class L>
  static void vertex(const typename L::VertexIn& in, typename L::VertexOut& out,
                     const Uniforms& u) {
    using vec4 = typename L::vec4;
    PositionNormalVS::vertex<L>(in, out, u);
    const vec4 c = out.position;
    // ndc z' = near + k (1 + ndc z), in [near, near + 2k]: behind every undilated surface.
    constexpr float k = (1.0f - kDilationDepthNear) * 0.25f;
    out.position =
        vec4(sl::x(c), sl::y(c), sl::w(c) * (kDilationDepthNear + k) + sl::z(c) * k, sl::w(c));
  }
};

}  // namespace skinsim::pipeline::shaders
