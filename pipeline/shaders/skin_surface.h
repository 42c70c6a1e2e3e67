// What every skin shader starts with: three independent reads, in this order (albedo +
// reflectivity and the normal map at the mesh UV, the cosine-filtered environment along
// the vertex normal), the key light's shadow-map fetches when there are shadows (every skin
// pass needs them: at least the specular is shadowed), and the per-pixel terms derived. Shaders
// that read more textures read them after these, so every technique's skin pass fetches in the same
// order.
#pragma once

#include "pipeline/shaders/gamma.h"
#include "pipeline/shaders/normal_mapping.h"
#include "pipeline/shaders/skin_uniforms.h"
#include "pipeline/shaders/surface_vs.h"

namespace skinsim::pipeline::shaders {

template <class L>
struct SkinSurface {
  typename L::vec4 environment;  // rgb: diffuse environment light along the vertex normal
  typename L::vec3 normal;       // normal-mapped
  typename L::vec3 vertex_normal;
  typename L::vec3 view;
  typename L::vec3 albedo;  // linear
  typename L::f32 reflectivity;
  typename L::f32 n_dot_l;     // key light, signed, normal-mapped
  typename L::f32 visibility;  // of the key light (lights.h)
};

// The per-pixel terms from the albedo and normal-map samples, and the key light's shadow-map
// fetches (everything but the environment read).
template <class L, GammaMode kGamma>
void surface_terms(const typename L::FragIn& in, typename L::TexUnit& tex, const SkinUniforms& u,
                   const typename L::vec4& base, const typename L::vec4& normal_map,
                   SkinSurface<L>& s) {
  using vec3 = typename L::vec3;
  s.vertex_normal = sl::normalize(in.v3(SurfaceSlots::kNormal));
  s.normal = normal_mapped<L>(s.vertex_normal, in.v4(SurfaceSlots::kTangent), normal_map);
  s.visibility = key_visibility<L>(in, tex, u.lights, SurfaceSlots::kLight);
  s.view = sl::normalize(vec3(u.eye) - in.v3(SurfaceSlots::kWorldPos));
  s.n_dot_l = sl::dot(s.normal, vec3(u.lights.direction[0]));
  s.albedo = decode_gamma<kGamma>(sl::xyz(base)) * u.albedo_factor;
  s.reflectivity = sl::w(base) * u.reflectivity;
}

template <class L, GammaMode kGamma>
SkinSurface<L> skin_surface(const typename L::FragIn& in, typename L::TexUnit& tex,
                            const SkinUniforms& u) {
  using vec4 = typename L::vec4;
  const vec4 base = tex.sample(SkinBindings::kAlbedo, in.texcoord(SurfaceSlots::kUv));
  const vec4 normal_map = tex.sample(SkinBindings::kNormalMap, in.texcoord(SurfaceSlots::kUv));
  SkinSurface<L> s;
  s.environment = tex.sample_cube(SkinBindings::kEnvironment, in.direction(SurfaceSlots::kNormal));
  surface_terms<L, kGamma>(in, tex, u, base, normal_map, s);
  return s;
}

}  // namespace skinsim::pipeline::shaders
