// Light wrapping (docs/skin-techniques.md section 5): diffuse = max(0, (N.L + w) / (1 + w))
// with the normal-mapped normal, one pass, no LUT for the diffuse part. The cheapest way to
// soften the terminator; it brightens the shadow side without skin's red shift.
#pragma once

#include "pipeline/shaders/specular.h"

namespace skinsim::pipeline::shaders {

template <GammaMode kGamma, SpecularModel kSpec>
struct WrapFS {
  static constexpr ShaderName kNameText =
      shader_name({"wrap_fs", specular_suffix(kSpec), gamma_suffix(kGamma)});
  static constexpr const char* kName = kNameText.text;
  using Uniforms = TechniqueUniforms;
  SKINSIM_SL_FRAGMENT {
    SKINSIM_SL_TYPES(L);
    const SkinSurface<L> s = skin_surface<L, kGamma>(in, tex, u);
    const vec3 key_vis = tinted<L>(s.visibility, u.lights);
    vec3 diffuse_light = vec3(u.lights.ambient) +
                         transmitted<L>(in, s.vertex_normal, u.lights, SurfaceSlots::kLight);
    for (int i = 0; i < u.lights.count; ++i) {
      const auto n_dot_l = sl::dot(s.normal, vec3(u.lights.direction[i]));
      const auto wrapped = sl::saturate((n_dot_l + u.wrap) * (1.0f / (1.0f + u.wrap)));
      diffuse_light = diffuse_light + light_radiance<L>(i, key_vis, u.lights) * wrapped;
    }
    return skin_color<kGamma, kSpec, L>(s, tex, u, diffuse_light);
  }
};

}  // namespace skinsim::pipeline::shaders
