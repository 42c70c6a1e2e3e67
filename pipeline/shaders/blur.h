// Pass 2 of the GPU Pro 5 pipeline: one axis of a separable Gaussian over the integration
// buffer, normalised by the taps' alpha (skin coverage) so light does not leak between skin
// and background. The buffer is premultiplied (rgb = light x coverage; the background is
// cleared to 0), which keeps the normalisation exact under bilinear filtering at the edge. Tap
// coordinates are computed in the vertex shader and interpolated, so every tap is an independent
// read (PowerVR performance guidelines).
#pragma once

#include <array>
#include <glm/glm.hpp>

#include "sim/shader_io.h"

namespace skinsim::pipeline::shaders {

namespace sl = sim::sl;

constexpr int kBlurTaps = 9;  // centre + 4 per side: 18 varying floats, within GLES2's 8 vec4

struct BlurVS {
  static constexpr const char* kName = "blur_vs";
  struct Uniforms {
    std::array<glm::vec2, kBlurTaps> offsets{};  // in texture coordinates
  };
  // Attributes: position already in clip space, uv in [0,1] over the source buffer.
  template <class L>
  static void vertex(const typename L::VertexIn& in, typename L::VertexOut& out,
                     const Uniforms& u) {
    using vec4 = typename L::vec4;
    using vec2 = typename L::vec2;
    const auto p = in.position();
    out.position = vec4(sl::x(p), sl::y(p), 0.0f, 1.0f);
    const auto uv = in.uv();
    for (int i = 0; i < kBlurTaps; ++i) out.set(2 * i, uv + vec2(u.offsets[i]));
  }
};

struct BlurFS {
  static constexpr const char* kName = "blur_fs";
  struct Uniforms {
    std::array<float, kBlurTaps> weights{};  // Gaussian weights, centre is tap kBlurTaps/2
  };
  SKINSIM_SL_FRAGMENT {
    SKINSIM_SL_TYPES(L);
    vec3 sum(0.0f);
    f32 weight_sum(0.0f);
    const auto taps = sl::sample_each<kBlurTaps>(tex, 0, [&](int i) { return in.texcoord(2 * i); });
    for (int i = 0; i < kBlurTaps; ++i) {
      const vec4& t = taps[i];
      sum = sum + sl::xyz(t) * u.weights[i];              // premultiplied light
      weight_sum = weight_sum + sl::w(t) * u.weights[i];  // skin coverage of the taps
    }
    const vec4& centre = taps[kBlurTaps / 2];
    // Normalised light where there is skin, premultiplied again by the centre's coverage.
    const vec3 blurred = sum * (sl::w(centre) / sl::max(weight_sum, 1e-4f));
    return vec4(blurred, sl::w(centre));
  }
};

// The depth-aware variant (blur_follow_mm): the buffer's alpha is a depth code (0 = no skin;
// IrradianceFS::depth_code), the rgb not premultiplied, and the taps are nearest reads at
// whole texels (so codes never blend). A tap's weight fades with its depth's distance from
// the centre's (a tent `1 / codes_per_tolerance` codes wide) and is 0 on background, as
// Jimenez et al.'s "follow surface". The last axis writes what SkinFS reads: rgb
// premultiplied by coverage, alpha = coverage. ~5 ALU ops more per tap, no more reads.
struct DepthAwareBlurFS {
  static constexpr const char* kName = "blur_follow_fs";
  struct Uniforms {
    std::array<float, kBlurTaps> weights{};
    float codes_per_tolerance = 1.0f;
    bool last_axis = false;
  };
  SKINSIM_SL_FRAGMENT {
    SKINSIM_SL_TYPES(L);
    const vec4 centre = tex.sample(0, in.texcoord(2 * (kBlurTaps / 2)));
    vec3 sum(0.0f);
    f32 weight_sum(0.0f);
    for (int i = 0; i < kBlurTaps; ++i) {
      const vec4 t = i == kBlurTaps / 2 ? centre : tex.sample(0, in.texcoord(2 * i));
      const auto same_surface =
          sl::saturate(1.0f - sl::abs(sl::w(t) - sl::w(centre)) * u.codes_per_tolerance) *
          sl::step(0.5f / 255.0f, sl::w(t));
      const auto w = same_surface * u.weights[i];
      sum = sum + sl::xyz(t) * w;
      weight_sum = weight_sum + w;
    }
    const auto covered = sl::step(0.5f / 255.0f, sl::w(centre));
    const vec3 blurred = sum * (covered * sl::rcp(sl::max(weight_sum, 1e-4f)));
    return u.last_axis ? vec4(blurred, covered) : vec4(blurred, sl::w(centre));
  }
};

}  // namespace skinsim::pipeline::shaders
