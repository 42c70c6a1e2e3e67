// Pass 3 of the GPU Pro 5 mobile skin pipeline, and its single-pass LOD variant.
//
// Final shading reads exactly four independent textures (albedo + reflectivity, normal
// map, the environment cube along the per-vertex normal, the blurred irradiance buffer)
// and one dependent texture, the BRDF LUT at (N.H, N.V), whose LOD selects roughness.
// Diffuse light is the two-layer mix: the sharp per-pixel light (epidermis) and the
// blurred buffer (subdermal scattering), mixed per channel (diffusion.h), times albedo and
// the LUT's energy-conservation term. Specular is the LUT's two Kelemen/Szirmay-Kalos lobes;
// the environment is scaled by the LUT's pre-integrated Fresnel and the reflectivity map.
#pragma once

#include "pipeline/shaders/gamma.h"
#include "pipeline/shaders/irradiance.h"
#include "pipeline/bake/brdf_lut_encoding.h"
#include "pipeline/shaders/surface_vs.h"

namespace skinsim::pipeline::shaders {

struct SkinBindings {
  static constexpr int kAlbedo = 0;
  static constexpr int kNormalMap = 1;
  static constexpr int kEnvironment = 2;
  static constexpr int kIrradiance = 3;
  static constexpr int kBrdfLut = 4;
};

struct SkinUniforms {
  glm::vec3 eye{0.0f};
  glm::vec3 light_dir{0.0f, 0.0f, 1.0f};
  glm::vec3 light_radiance{1.0f};
  glm::vec3 ambient{0.0f};
  glm::vec3 albedo_factor{1.0f};
  glm::vec3 layer_mix{0.5f};  // fraction of each channel's diffuse light that scatters wide
  float reflectivity = 1.0f;
  float specular_intensity = 0.18f;  // rho_s
  float lobe1_weight = 0.85f;
  float lobe2_weight = 0.15f;
  float lut_lod = 0.0f;
  float environment_intensity = 1.0f;
};

// The per-pixel surface terms both skin shaders share.
template <class L>
struct SkinSurface {
  typename L::vec3 normal;      // normal-mapped
  typename L::vec3 vertex_normal;
  typename L::vec3 albedo;      // linear
  typename L::f32 reflectivity;
  typename L::f32 n_dot_l;
  typename L::vec4 lut;
};

template <class L, GammaMode kGamma>
SkinSurface<L> skin_surface(const typename L::FragIn& in, typename L::TexUnit& tex,
                            const SkinUniforms& u, const typename L::vec4& base,
                            const typename L::vec4& normal_map) {
  using vec2 = typename L::vec2;
  using vec3 = typename L::vec3;
  SkinSurface<L> s;
  s.vertex_normal = sl::normalize(in.v3(SurfaceSlots::kNormal));
  const auto tangent4 = in.v4(SurfaceSlots::kTangent);
  const vec3 tangent = sl::xyz(tangent4);
  const vec3 bitangent = sl::cross(s.vertex_normal, tangent) * sl::w(tangent4);
  const vec3 nt = sl::xyz(normal_map) * 2.0f - 1.0f;
  s.normal = sl::normalize(tangent * sl::x(nt) + bitangent * sl::y(nt) +
                           s.vertex_normal * sl::z(nt));
  const vec3 view = sl::normalize(vec3(u.eye) - in.v3(SurfaceSlots::kWorldPos));
  const vec3 half = sl::normalize(view + vec3(u.light_dir));
  s.n_dot_l = sl::dot(s.normal, vec3(u.light_dir));
  const auto n_dot_h = sl::saturate(sl::dot(s.normal, half));
  const auto n_dot_v = sl::saturate(sl::dot(s.normal, view));
  s.lut = tex.sample_lod(SkinBindings::kBrdfLut, vec2(n_dot_h, n_dot_v), u.lut_lod);
  s.albedo = decode_gamma<kGamma>(sl::xyz(base)) * u.albedo_factor;
  s.reflectivity = sl::w(base) * u.reflectivity;
  return s;
}

// Specular (two LUT lobes, lit by the key light) plus environment rim light.
template <class L>
typename L::vec3 skin_reflection(const SkinSurface<L>& s, const typename L::vec4& env,
                                 const SkinUniforms& u) {
  using vec3 = typename L::vec3;
  const auto lobes = bake::decode_specular_lobe(sl::x(s.lut)) * u.lobe1_weight +
                     bake::decode_specular_lobe(sl::y(s.lut)) * u.lobe2_weight;
  const auto specular = lobes * sl::saturate(s.n_dot_l) * u.specular_intensity * s.reflectivity;
  const auto fresnel = bake::decode_fresnel(sl::z(s.lut));
  return vec3(u.light_radiance) * specular +
         sl::xyz(env) * (fresnel * s.reflectivity * u.environment_intensity);
}

template <GammaMode kGamma>
struct SkinFS {
  static constexpr const char* kName =
      kGamma == GammaMode::kSquare ? "skin_fs" : "skin_fs_srgb";
  using Uniforms = SkinUniforms;
  template <class L>
  static typename L::vec4 fragment(const typename L::FragIn& in, typename L::TexUnit& tex,
                                   const Uniforms& u) {
    using vec3 = typename L::vec3;
    using vec4 = typename L::vec4;
    const vec4 base = tex.sample(SkinBindings::kAlbedo, in.texcoord(SurfaceSlots::kUv));
    const vec4 normal_map = tex.sample(SkinBindings::kNormalMap, in.texcoord(SurfaceSlots::kUv));
    const vec4 env = tex.sample_cube(SkinBindings::kEnvironment, in.direction(SurfaceSlots::kNormal));
    const vec4 buffer = tex.sample(SkinBindings::kIrradiance, in.screen_texcoord());
    const SkinSurface<L> s = skin_surface<L, kGamma>(in, tex, u, base, normal_map);

    const vec3 sharp = vec3(u.light_radiance) * sl::saturate(s.n_dot_l) + vec3(u.ambient);
    // The buffer holds blurred light premultiplied by coverage a; where a < 1 (silhouettes)
    // the sharp light fills in: mix(sharp, blurred / a, layer_mix * a).
    const vec3 wide = vec3(u.layer_mix);
    const vec3 diffuse_light = sharp * (1.0f - wide * sl::w(buffer)) +
                               sl::xyz(buffer) * (wide * kIrradianceRange);
    const vec3 color = s.albedo * diffuse_light * bake::decode_diffuse_energy(sl::w(s.lut)) +
                       skin_reflection<L>(s, env, u);
    return vec4(encode_gamma<kGamma>(color), 1.0f);
  }
};

// Distant skin: one pass, no buffer. Scattering is approximated by bending each channel's
// normal toward the vertex normal by that channel's scattering fraction (GPU Pro 5 LOD).
template <GammaMode kGamma>
struct SkinLodFS {
  static constexpr const char* kName =
      kGamma == GammaMode::kSquare ? "skin_lod_fs" : "skin_lod_fs_srgb";
  using Uniforms = SkinUniforms;
  template <class L>
  static typename L::vec4 fragment(const typename L::FragIn& in, typename L::TexUnit& tex,
                                   const Uniforms& u) {
    using vec3 = typename L::vec3;
    using vec4 = typename L::vec4;
    const vec4 base = tex.sample(SkinBindings::kAlbedo, in.texcoord(SurfaceSlots::kUv));
    const vec4 normal_map = tex.sample(SkinBindings::kNormalMap, in.texcoord(SurfaceSlots::kUv));
    const vec4 env = tex.sample_cube(SkinBindings::kEnvironment, in.direction(SurfaceSlots::kNormal));
    const SkinSurface<L> s = skin_surface<L, kGamma>(in, tex, u, base, normal_map);

    const vec3 l(u.light_dir);
    const vec3 n_r = sl::normalize(sl::mix(s.normal, s.vertex_normal, u.layer_mix.r));
    const vec3 n_g = sl::normalize(sl::mix(s.normal, s.vertex_normal, u.layer_mix.g));
    const vec3 n_b = sl::normalize(sl::mix(s.normal, s.vertex_normal, u.layer_mix.b));
    const vec3 n_dot_l = sl::saturate(vec3(sl::dot(n_r, l), sl::dot(n_g, l), sl::dot(n_b, l)));
    const vec3 diffuse_light = vec3(u.light_radiance) * n_dot_l + vec3(u.ambient);
    const vec3 color = s.albedo * diffuse_light * bake::decode_diffuse_energy(sl::w(s.lut)) +
                       skin_reflection<L>(s, env, u);
    return vec4(encode_gamma<kGamma>(color), 1.0f);
  }
};

}  // namespace skinsim::pipeline::shaders
