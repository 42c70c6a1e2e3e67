// Final skin shading of the techniques that diffuse light in a separate buffer (burley,
// ssss: a full-resolution screen-space buffer; texture-space: a UV-space buffer). The
// buffer holds diffused irradiance (light only, no albedo); albedo is applied here, so the
// albedo texture stays sharp, and specular is evaluated here per pixel: it is never blurred
// (Jimenez et al. 2015 keep diffuse and specular apart for this reason).
#pragma once

#include "pipeline/shaders/specular.h"
#include "pipeline/shaders/technique_bindings.h"

namespace skinsim::pipeline::shaders {

enum class DiffusionSource {
  kScreen,  // RGBA16F screen buffer, rgb = diffused irradiance (read at the pixel)
  // RGBA16F UV-space buffer, rgb premultiplied by alpha = UV coverage (0 outside the UV
  // islands, so bilinear reads at island edges divide back to the skin's value).
  kUv,
};

template <GammaMode kGamma, SpecularModel kSpec, DiffusionSource kSource>
struct DiffusedSkinFS {
  static constexpr ShaderName kNameText =
      shader_name({kSource == DiffusionSource::kScreen ? "diffused_skin_fs" : "uv_diffused_skin_fs",
                   specular_suffix(kSpec), gamma_suffix(kGamma)});
  static constexpr const char* kName = kNameText.text;
  using Uniforms = TechniqueUniforms;
  SKINSIM_SL_FRAGMENT {
    SKINSIM_SL_TYPES(L);
    using B = TechniqueBindings;
    const SkinSurface<L> s = skin_surface<L, kGamma>(in, tex, u);
    vec3 diffuse_light(0.0f);
    if constexpr (kSource == DiffusionSource::kScreen) {
      diffuse_light = sl::xyz(tex.sample(B::kDiffusion, in.screen_texcoord()));
    } else {
      const vec4 buffer = tex.sample(B::kDiffusion, in.texcoord(SurfaceSlots::kUv));
      // Texels with no UV coverage nearby (alpha 0) fall back to the sharp light.
      const vec3 sharp =
          lambert_irradiance<L>(s.normal, tinted<L>(s.visibility, u.lights), u.lights);
      const vec3 diffused = sl::xyz(buffer) * sl::rcp(sl::max(sl::w(buffer), 1.0f / 255.0f));
      diffuse_light = sl::mix(sharp, diffused, sl::w(buffer));
    }
    return skin_color<kGamma, kSpec, L>(s, tex, u, diffuse_light);
  }
};

}  // namespace skinsim::pipeline::shaders
