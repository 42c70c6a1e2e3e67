// Pass 1 of the GPU Pro 5 mobile skin pipeline: incoming light only (no albedo) into the
// reduced-resolution integration buffer; alpha = 1 marks skin coverage.
#pragma once

#include "pipeline/shaders/surface_vs.h"

namespace skinsim::pipeline::shaders {

// The buffer is RGBA8: irradiance is stored divided by this range so values up to 2x the
// key light's radiance survive without clipping.
constexpr float kIrradianceRange = 2.0f;

struct IrradianceFS {
  static constexpr const char* kName = "skin_irradiance_fs";
  struct Uniforms {
    glm::vec3 light_dir{0.0f, 0.0f, 1.0f};  // towards the light
    glm::vec3 light_radiance{1.0f};
    glm::vec3 ambient{0.0f};
  };
  template <class L>
  static typename L::vec4 fragment(const typename L::FragIn& in, typename L::TexUnit&,
                                   const Uniforms& u) {
    using vec3 = typename L::vec3;
    using vec4 = typename L::vec4;
    const vec3 n = sl::normalize(in.v3(0));
    const auto n_dot_l = sl::saturate(sl::dot(n, vec3(u.light_dir)));
    const vec3 irradiance = vec3(u.light_radiance) * n_dot_l + vec3(u.ambient);
    return vec4(irradiance * (1.0f / kIrradianceRange), 1.0f);
  }
};

}  // namespace skinsim::pipeline::shaders
