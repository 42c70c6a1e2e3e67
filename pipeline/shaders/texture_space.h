// Passes of texture-space diffusion (d'Eon & Luebke, GPU Gems 3 ch. 14):
//   uv_irradiance: the skin mesh rasterised into its UV layout (clip position = uv * 2 - 1),
//                  normal-mapped irradiance per texel, alpha = 1 on the UV islands. This
//                  needs non-overlapping UVs on the skin (true of the built-in head and of
//                  LeePerrySmith): overlapping islands would share, and mix, texels.
//   uv_blur_<i>_h/_v: one separable Gaussian per profile term, each from the previous
//                  (variances add), with the mobile pipeline's mask-aware blur (blur.h).
//   uv_combine:    the weighted sum of irradiance and the five blurred textures.
// The final `skin` pass reads the combined texture with the mesh UV (diffused_skin.h).
#pragma once

#include <array>

#include "pipeline/shaders/screen_diffusion.h"
#include "pipeline/shaders/surface_vs.h"

namespace skinsim::pipeline::shaders {

struct UvSpaceVS {
  static constexpr const char* kName = "uv_space_vs";
  struct Uniforms {
    LightVertexUniforms light;
  };
  static constexpr int kNormal = 0;
  static constexpr int kTangent = 3;
  static constexpr int kUv = 7;
  static constexpr LightVaryings kLight{9, 12};
  template <class L>
  static void vertex(const typename L::VertexIn& in, typename L::VertexOut& out,
                     const Uniforms& u) {
    using vec4 = typename L::vec4;
    const auto uv = in.uv();
    // Texture rows grow downwards (v = 0 at the top), clip y upwards.
    out.position = vec4(sl::x(uv) * 2.0f - 1.0f, 1.0f - sl::y(uv) * 2.0f, 0.0f, 1.0f);
    out.set(kNormal, in.normal());
    out.set(kTangent, in.tangent());
    out.set(kUv, uv);
    write_light_varyings<L>(in, out, u.light, in.position(), in.normal(), kLight);
  }
};

struct UvIrradianceFS {
  static constexpr const char* kName = "uv_irradiance_fs";
  struct Uniforms {
    LightUniforms lights;
  };
  static constexpr int kNormalMap = 1;
  SKINSIM_SL_FRAGMENT {
    SKINSIM_SL_TYPES(L);
    const vec4 normal_map = tex.sample(kNormalMap, in.texcoord(UvSpaceVS::kUv));
    const vec3 vertex_normal = sl::normalize(in.v3(UvSpaceVS::kNormal));
    const vec3 n = normal_mapped<L>(vertex_normal, in.v4(UvSpaceVS::kTangent), normal_map);
    const auto visibility = key_visibility<L>(in, tex, u.lights, UvSpaceVS::kLight);
    const vec3 irradiance = lambert_irradiance<L>(n, tinted<L>(visibility, u.lights), u.lights) +
                            transmitted<L>(in, vertex_normal, u.lights, UvSpaceVS::kLight);
    return vec4(irradiance, 1.0f);
  }
};

// The six profile terms' textures (irradiance first) weighted per channel; all six reads
// are independent (same UV varying), within the SGX's eight texture units.
inline constexpr int kTextureSpaceTerms = 6;

struct UvCombineFS {
  static constexpr const char* kName = "uv_combine_fs";
  struct Uniforms {
    std::array<glm::vec3, kTextureSpaceTerms> weights{};
  };
  SKINSIM_SL_FRAGMENT {
    SKINSIM_SL_TYPES(L);
    const auto uv = in.texcoord(0);
    const vec4 first = tex.sample(0, uv);
    vec3 sum = sl::xyz(first) * vec3(u.weights[0]);
    for (int i = 1; i < kTextureSpaceTerms; ++i) {
      sum = sum + sl::xyz(tex.sample(i, uv)) * vec3(u.weights[i]);
    }
    return vec4(sum, sl::w(first));
  }
};

}  // namespace skinsim::pipeline::shaders
