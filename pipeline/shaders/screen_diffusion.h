// Passes of the full-resolution screen-space diffusion techniques (burley, ssss):
//   diffuse: normal-mapped irradiance of the key light plus ambient (no albedo, no
//            specular), alpha = view distance in mm (0 = no skin). RGBA16F: irradiance
//            above 1 survives, and half floats hold distances of a few metres to ~0.5 mm.
//            A colour target carrying depth is what a GLES2 app on SGX does (no depth
//            texture sampling without extensions), so its bandwidth is counted like any.
//   sss:     Burley normalized diffusion, one 2D pass of importance-sampled taps
//            (Golubev 2018), or sss_h + sss_v: Jimenez's separable kernel (2015).
// Tap positions depend on the centre pixel's depth (the kernel is in mm on the skin), so
// every tap but the centre is a dependent read. A tap that lands on a surface at a
// different depth (or on background) is replaced by the centre value ("follow surface",
// Jimenez et al.), which keeps light from bleeding across silhouettes.
#pragma once

#include <array>
#include <utility>

#include "pipeline/config.h"
#include "pipeline/shaders/normal_mapping.h"
#include "pipeline/shaders/surface_vs.h"

namespace skinsim::pipeline::shaders {

// Full-target quad with screen coordinates in slot 0 (passes that read the screen buffer
// at their own pixel use screen_texcoord(); slot 0 is for UV-space quads).
struct QuadVS {
  static constexpr const char* kName = "quad_vs";
  struct Uniforms {};
  template <class L>
  static void vertex(const typename L::VertexIn& in, typename L::VertexOut& out, const Uniforms&) {
    using vec4 = typename L::vec4;
    const auto p = in.position();
    out.position = vec4(sl::x(p), sl::y(p), 0.0f, 1.0f);
    out.set(0, in.uv());
  }
};

// Normal-mapped irradiance of the lights (the key light shadowed) plus ambient and the
// transmitted light at a skin fragment.
template <class L>
typename L::vec3 skin_irradiance(const typename L::FragIn& in, typename L::TexUnit& tex,
                                 int normal_map_unit, const LightUniforms& lights) {
  using vec3 = typename L::vec3;
  const typename L::vec4 normal_map = tex.sample(normal_map_unit, in.texcoord(SurfaceSlots::kUv));
  const vec3 vertex_normal = sl::normalize(in.v3(SurfaceSlots::kNormal));
  const vec3 n = normal_mapped<L>(vertex_normal, in.v4(SurfaceSlots::kTangent), normal_map);
  const auto visibility = key_visibility<L>(in, tex, lights, SurfaceSlots::kLight);
  return lambert_irradiance<L>(n, tinted<L>(visibility, lights), lights) +
         transmitted<L>(in, vertex_normal, lights, SurfaceSlots::kLight);
}

struct DiffuseDepthFS {
  static constexpr const char* kName = "diffuse_depth_fs";
  struct Uniforms {
    glm::vec3 eye{0.0f};
    LightUniforms lights;
    float mm_per_unit = 1.0f;
  };
  static constexpr int kNormalMap = 1;
  SKINSIM_SL_FRAGMENT {
    SKINSIM_SL_TYPES(L);
    const vec3 irradiance = skin_irradiance<L>(in, tex, kNormalMap, u.lights);
    const auto depth_mm = sl::length(vec3(u.eye) - in.v3(SurfaceSlots::kWorldPos)) * u.mm_per_unit;
    return vec4(irradiance, depth_mm);
  }
};

// Orthographic views: alpha is the depth beyond the near plane in mm plus 1 mm (0 stays
// "no skin"); the kernels use only depth differences, their scale being the same at every
// depth.
struct DiffuseDepthOrthoFS {
  static constexpr const char* kName = "diffuse_depth_ortho_fs";
  struct Uniforms {
    glm::vec3 depth_axis{0.0f, 0.0f, -1.0f};  // view direction * mm per unit
    float depth_offset = 1.0f;                // mm
    LightUniforms lights;
  };
  static constexpr int kNormalMap = DiffuseDepthFS::kNormalMap;
  SKINSIM_SL_FRAGMENT {
    SKINSIM_SL_TYPES(L);
    const vec3 irradiance = skin_irradiance<L>(in, tex, kNormalMap, u.lights);
    const auto depth_mm =
        sl::dot(vec3(u.depth_axis), in.v3(SurfaceSlots::kWorldPos)) + u.depth_offset;
    return vec4(irradiance, depth_mm);
  }
};

// Uniforms shared by the two kernels: uv per mm at depth 1 mm per axis (focal length in
// pixels over the target size; orthographic views: uv per mm at any depth), and the
// follow-surface depth tolerance.
struct ScreenKernelUniforms {
  glm::vec2 focal_uv{1.0f};
  float inv_follow_mm = 0.25f;  // 1 / depth difference (mm) at which a tap is fully replaced
};

// A kernel tap's light, following the surface: replaced by the centre's light as the tap's
// depth (alpha, mm) departs from the centre's, fully at 1 / inv_follow_mm (Jimenez et al.).
template <class L, class Scalar>
typename L::vec3 follow_surface(const typename L::vec4& tap, const typename L::vec4& centre,
                                const Scalar& depth, const ScreenKernelUniforms& u) {
  const auto off_surface = sl::saturate(sl::abs(sl::w(tap) - depth) * u.inv_follow_mm);
  return sl::mix(sl::xyz(tap), sl::xyz(centre), off_surface);
}

// The kernels' uv per mm: divided by the centre's depth for perspective views, the same
// at every depth for orthographic ones (a separate program, so perspective ones keep their
// op counts).
template <bool kOrthographic, class L, class Scalar>
typename L::vec2 uv_per_mm_at(const glm::vec2& focal_uv, const Scalar& depth_mm) {
  using vec2 = typename L::vec2;
  if constexpr (kOrthographic) {
    return vec2(focal_uv);
  } else {
    return vec2(focal_uv) * sl::rcp(sl::max(depth_mm, 1.0f));
  }
}

// What every screen-space kernel reads first: its pixel's screen uv, the centre texel of
// binding 0 (its depth in mm in w) and the texture uv per mm at that depth, for
// `const auto [screen, centre, depth, uv_per_mm] = kernel_centre<kOrthographic, L>(...)`.
template <class L>
struct KernelCentre {
  decltype(std::declval<const typename L::FragIn&>().screen_texcoord()) screen;
  typename L::vec4 centre;
  decltype(sl::w(std::declval<typename L::vec4>())) depth;
  typename L::vec2 uv_per_mm;
};

template <bool kOrthographic, class L>
KernelCentre<L> kernel_centre(const typename L::FragIn& in, typename L::TexUnit& tex,
                              const glm::vec2& focal_uv) {
  const auto screen = in.screen_texcoord();
  const typename L::vec4 centre = tex.sample(0, screen);
  const auto depth = sl::w(centre);
  return {screen, centre, depth, uv_per_mm_at<kOrthographic, L>(focal_uv, depth)};
}

// A per-pixel angle in [0, 2 pi) from interleaved gradient noise over the screen uv (Jimenez
// 2014; noise_uv = (0.06711056 width, 0.00583715 height)): turning a disc of taps by it makes
// a tap's share show as fine noise rather than a shifted copy of what it lands on.
template <class L>
auto interleaved_gradient_angle(const typename L::vec2& screen_uv, const glm::vec2& noise_uv) {
  using vec2 = typename L::vec2;
  return sl::fract(sl::fract(sl::dot(screen_uv, vec2(noise_uv))) * 52.9829189f) * 6.2831853f;
}

// Burley normalized diffusion: `count` taps at precomputed offsets (mm, a Fibonacci spiral
// with radii from the inverse CDF of the widest channel), RGB weights R_c(r) / pdf(r)
// normalised per channel (techniques/kernels.h). The centre is read once, independently.
struct BurleyUniforms : ScreenKernelUniforms {
  int count = 0;
  std::array<glm::vec2, kMaxBurleySamples> offsets_mm{};
  std::array<glm::vec3, kMaxBurleySamples> weights{};
};

template <bool kOrthographic>
struct BurleyFSFor {
  static constexpr const char* kName = kOrthographic ? "burley_sss_ortho_fs" : "burley_sss_fs";
  using Uniforms = BurleyUniforms;
  SKINSIM_SL_FRAGMENT {
    SKINSIM_SL_TYPES(L);
    const auto [screen, centre, depth, uv_per_mm] =
        kernel_centre<kOrthographic, L>(in, tex, u.focal_uv);
    vec3 sum(0.0f);
    for (int i = 0; i < u.count; ++i) {
      const vec4 t = tex.sample(0, screen.value + vec2(u.offsets_mm[i]) * uv_per_mm);
      sum = sum + follow_surface<L>(t, centre, depth, u) * vec3(u.weights[i]);
    }
    return vec4(sum, depth);
  }
};

// One axis of Jimenez's separable SSS (2015): a centre tap plus kSsssTaps - 1 taps at 1D
// offsets (mm) along the axis, RGB weights of the six-Gaussian profile (techniques/kernels.h).
inline constexpr int kSsssTaps = 17;  // Jimenez's default quality

struct SsssBlurUniforms : ScreenKernelUniforms {
  glm::vec2 axis{1.0f, 0.0f};
  std::array<float, kSsssTaps> offsets_mm{};  // tap 0 is the centre (offset 0)
  std::array<glm::vec3, kSsssTaps> weights{};
};

template <bool kOrthographic>
struct SsssBlurFSFor {
  static constexpr const char* kName = kOrthographic ? "ssss_blur_ortho_fs" : "ssss_blur_fs";
  using Uniforms = SsssBlurUniforms;
  SKINSIM_SL_FRAGMENT {
    SKINSIM_SL_TYPES(L);
    const auto [screen, centre, depth, step] =
        kernel_centre<kOrthographic, L>(in, tex, u.focal_uv * u.axis);
    vec3 sum = sl::xyz(centre) * vec3(u.weights[0]);
    const auto taps = sl::sample_each<kSsssTaps - 1>(
        tex, 0, [&](int i) { return screen.value + step * u.offsets_mm[i + 1]; });
    for (int i = 1; i < kSsssTaps; ++i) {
      sum = sum + follow_surface<L>(taps[i - 1], centre, depth, u) * vec3(u.weights[i]);
    }
    return vec4(sum, depth);
  }
};

using BurleyFS = BurleyFSFor<false>;
using BurleyOrthoFS = BurleyFSFor<true>;
using SsssBlurFS = SsssBlurFSFor<false>;
using SsssBlurOrthoFS = SsssBlurFSFor<true>;

}  // namespace skinsim::pipeline::shaders
