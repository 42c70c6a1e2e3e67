// Pass 1 of the GPU Pro 5 mobile skin pipeline: incoming light only (no albedo) into the
// reduced-resolution integration buffer; alpha = 1 marks skin coverage. The key light's
// shadow is sampled here, so the blur softens and reddens its edge, and transmission is
// added here, as scattered light.
#pragma once

#include "pipeline/shaders/surface_vs.h"

namespace skinsim::pipeline::shaders {

// The buffer is RGBA8: irradiance is stored divided by this range so values up to 2x the
// key light's radiance survive without clipping.
constexpr float kIrradianceRange = 2.0f;

struct IrradianceFS {
  static constexpr const char* kName = "skin_irradiance_fs";
  struct Uniforms {
    LightUniforms lights;
    // Depth-aware blur (blur_follow_mm): alpha = view depth coded 1/255..1 over
    // [depth_near_mm, depth_near_mm + 1 / inv_depth_range_mm] instead of coverage 1 (0 stays
    // "no skin").
    bool depth_code = false;
    float depth_near_mm = 0.0f;
    float inv_depth_range_mm = 1.0f;
  };
  SKINSIM_SL_FRAGMENT {
    SKINSIM_SL_TYPES(L);
    const vec3 n = sl::normalize(in.v3(0));
    const auto visibility = key_visibility<L>(in, tex, u.lights, PositionNormalVS::kLight);
    const vec3 irradiance = lambert_irradiance<L>(n, tinted<L>(visibility, u.lights), u.lights) +
                            transmitted<L>(in, n, u.lights, PositionNormalVS::kLight);
    if (u.depth_code) {
      const auto code = sl::saturate((in.f(PositionNormalVS::kViewDepth) - u.depth_near_mm) *
                                     u.inv_depth_range_mm) *
                            (254.0f / 255.0f) +
                        (1.0f / 255.0f);
      return vec4(irradiance * (1.0f / kIrradianceRange), code);
    }
    return vec4(irradiance * (1.0f / kIrradianceRange), 1.0f);
  }
};

}  // namespace skinsim::pipeline::shaders
