// Lambert's cosine law with the normal-mapped normal and no subsurface scattering: the hard
// terminator and missing red shift every skin technique exists to soften.
#pragma once

#include "pipeline/shaders/specular.h"

namespace skinsim::pipeline::shaders {

template <GammaMode kGamma, SpecularModel kSpec>
struct LambertFS {
  static constexpr ShaderName kNameText =
      shader_name({"lambert_fs", specular_suffix(kSpec), gamma_suffix(kGamma)});
  static constexpr const char* kName = kNameText.text;
  using Uniforms = TechniqueUniforms;
  template <class L>
  static typename L::vec4 fragment(const typename L::FragIn& in, typename L::TexUnit& tex,
                                   const Uniforms& u) {
    using vec3 = typename L::vec3;
    using vec4 = typename L::vec4;
    const SkinSurface<L> s = skin_surface<L, kGamma>(in, tex, u);
    const vec3 key_vis = tinted<L>(s.visibility, u.lights);
    vec3 diffuse_light = vec3(u.lights.ambient) +
                         transmitted<L>(in, s.vertex_normal, u.lights, SurfaceSlots::kLight);
    for (int i = 0; i < u.lights.count; ++i) {
      const auto n_dot_l = sl::saturate(sl::dot(s.normal, vec3(u.lights.direction[i])));
      diffuse_light = diffuse_light + light_radiance<L>(i, key_vis, u.lights) * n_dot_l;
    }
    const Reflection<L> r = skin_specular<kSpec, L>(s, tex, u);
    const vec3 color = s.albedo * diffuse_light * r.diffuse_energy + r.light;
    return vec4(encode_gamma<kGamma>(color), 1.0f);
  }
};

}  // namespace skinsim::pipeline::shaders
