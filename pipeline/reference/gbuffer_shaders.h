// Shaders that write the reference renderer's G-buffer (RGBA32F targets), one quantity per
// pass: world position + material kind, shading normal + reflectivity, linear albedo, and
// the interpolated vertex normal.
#pragma once

#include "pipeline/shaders/gamma.h"
#include "pipeline/shaders/surface_vs.h"

namespace skinsim::pipeline::reference {

namespace sl = sim::sl;
using shaders::SurfaceSlots;

// Material kind codes stored in the position buffer's alpha (0 = nothing drawn).
constexpr float kKindSkin = 1.0f;
constexpr float kKindEye = 2.0f;
constexpr float kKindOther = 3.0f;

struct PositionFS {
  static constexpr const char* kName = "ref_position_fs";
  struct Uniforms {
    float kind = kKindOther;
  };
  template <class L>
  static typename L::vec4 fragment(const typename L::FragIn& in, typename L::TexUnit&,
                                   const Uniforms& u) {
    return typename L::vec4(in.v3(SurfaceSlots::kWorldPos), u.kind);
  }
};

struct ShadingNormalFS {
  static constexpr const char* kName = "ref_normal_fs";
  struct Uniforms {
    float reflectivity = 1.0f;
    bool normal_mapped = true;
  };
  template <class L>
  static typename L::vec4 fragment(const typename L::FragIn& in, typename L::TexUnit& tex,
                                   const Uniforms& u) {
    using vec3 = typename L::vec3;
    const vec3 nv = sl::normalize(in.v3(SurfaceSlots::kNormal));
    const auto base = tex.sample(0, in.texcoord(SurfaceSlots::kUv));
    if (!u.normal_mapped) return typename L::vec4(nv, sl::w(base) * u.reflectivity);
    const auto normal_map = tex.sample(1, in.texcoord(SurfaceSlots::kUv));
    const auto t4 = in.v4(SurfaceSlots::kTangent);
    const vec3 t = sl::xyz(t4);
    const vec3 b = sl::cross(nv, t) * sl::w(t4);
    const vec3 nt = sl::xyz(normal_map) * 2.0f - 1.0f;
    const vec3 n = sl::normalize(t * sl::x(nt) + b * sl::y(nt) + nv * sl::z(nt));
    return typename L::vec4(n, sl::w(base) * u.reflectivity);
  }
};

struct AlbedoFS {
  static constexpr const char* kName = "ref_albedo_fs";
  struct Uniforms {
    glm::vec3 factor{1.0f};
  };
  template <class L>
  static typename L::vec4 fragment(const typename L::FragIn& in, typename L::TexUnit& tex,
                                   const Uniforms& u) {
    const auto base = tex.sample(0, in.texcoord(SurfaceSlots::kUv));
    const auto linear = shaders::decode_gamma<GammaMode::kSrgb>(sl::xyz(base));
    return typename L::vec4(linear * u.factor, 1.0f);
  }
};

// rgb: the interpolated vertex normal; a: the baked thickness in mm (for transmission).
struct VertexNormalFS {
  static constexpr const char* kName = "ref_vertex_normal_fs";
  struct Uniforms {};
  template <class L>
  static typename L::vec4 fragment(const typename L::FragIn& in, typename L::TexUnit&,
                                   const Uniforms&) {
    return typename L::vec4(sl::normalize(in.v3(SurfaceSlots::kNormal)),
                            in.f(SurfaceSlots::kThickness));
  }
};

}  // namespace skinsim::pipeline::reference
