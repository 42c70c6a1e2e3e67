// The urp technique's screen-space ambient occlusion (the URP skin shader article's SSAO; URP's
// own ScreenSpaceAmbientOcclusion feature works the same way: a depth-normals pre-pass, the
// AO pass, a blur), as passes of the emulated GPU:
//   depth_normal: the skin's view-space vertex normal and view depth in mm (RGBA16F; a
//                 GLES2 app on the SGX writes depth to a colour target, as the screen-space
//                 diffusion techniques do; 0 = no skin);
//   ssao:         per pixel, `count` taps on a disc of fixed radius in mm on the skin (the
//                 disc turned per pixel by interleaved gradient noise, Jimenez 2014), each
//                 occluding by how far above the pixel's tangent plane its surface point lies
//                 (the cosine between the normal and the vector to it, less a bias, as the
//                 Alchemy AO of McGuire et al. 2011 and URP do) and fading with the depth gap,
//                 so background and far surfaces do not occlude;
//   ssao_h, ssao_v: the separable blur that removes the noise (blur_pass.h).
#pragma once

#include <array>

#include "pipeline/config.h"
#include "pipeline/shaders/screen_diffusion.h"

namespace skinsim::pipeline::shaders {

// The pre-pass's fragments: view-space normal (x right, y up, z towards the camera) and the
// view depth (mm) from PositionNormalVS's kViewDepth slot.
struct DepthNormalFS {
  static constexpr const char* kName = "depth_normal_fs";
  struct Uniforms {
    glm::vec3 right{1.0f, 0.0f, 0.0f};  // the camera's axes in world space
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    glm::vec3 back{0.0f, 0.0f, 1.0f};
  };
  template <class L>
  static typename L::vec4 fragment(const typename L::FragIn& in, typename L::TexUnit&,
                                   const Uniforms& u) {
    using vec3 = typename L::vec3;
    using vec4 = typename L::vec4;
    const vec3 n = sl::normalize(in.v3(0));
    return vec4(sl::dot(n, vec3(u.right)), sl::dot(n, vec3(u.up)), sl::dot(n, vec3(u.back)),
                in.f(PositionNormalVS::kViewDepth));
  }
};

// The occlusion of one tap: v is the vector from the pixel's surface point to the tap's (view
// space, mm), n the pixel's unit normal. Unoccluded (0) when the tap lies in or below the
// tangent plane; fades to 0 as the depth gap reaches kSsaoRangeMm.
inline constexpr float kSsaoBias = 0.1f;      // cosine, against self-occlusion on curved skin
inline constexpr float kSsaoRangeMm = 30.0f;  // a nose occludes a cheek; the background not
template <class L>
typename L::f32 ssao_tap_occlusion(const typename L::vec3& v, const typename L::vec3& n) {
  const auto cosine = sl::dot(v, n) * sl::rsqrt(sl::max(sl::dot(v, v), 1e-4f));
  const auto fade = sl::saturate(1.0f - sl::abs(sl::z(v)) * (1.0f / kSsaoRangeMm));
  return sl::saturate(cosine - kSsaoBias) * fade;
}

struct SsaoUniforms {
  glm::vec2 focal_uv{1.0f};  // as ScreenKernelUniforms
  glm::vec2 noise_uv{0.0f};  // as DipoleUniforms
  float strength = 1.0f;     // AO = 1 - strength * mean occlusion
  int count = 0;
  std::array<glm::vec2, kMaxSsaoTaps> offsets_mm{};  // view-space x (right), y (up)
};

template <bool kOrthographic>
struct SsaoFSFor {
  static constexpr const char* kName = kOrthographic ? "ssao_ortho_fs" : "ssao_fs";
  using Uniforms = SsaoUniforms;
  SKINSIM_SL_FRAGMENT {
    SKINSIM_SL_TYPES(L);
    const auto [screen, centre, depth, texture_uv_per_mm] =
        kernel_centre<kOrthographic, L>(in, tex, u.focal_uv);
    const vec3 n = sl::xyz(centre);
    // Texture v grows downwards, view y upwards.
    const vec2 uv_per_mm = texture_uv_per_mm * vec2(1.0f, -1.0f);
    const auto angle = interleaved_gradient_angle<L>(screen.value, u.noise_uv);
    const auto c = sl::cos(angle), s = sl::sin(angle);
    typename L::f32 occlusion(0.0f);
    for (int i = 0; i < u.count; ++i) {
      const glm::vec2 o = u.offsets_mm[i];
      const vec2 turned = vec2(c * o.x - s * o.y, s * o.x + c * o.y);
      const vec4 t = tex.sample(0, screen.value + turned * uv_per_mm);
      occlusion = occlusion + ssao_tap_occlusion<L>(vec3(turned, depth - sl::w(t)), n);
    }
    const auto ao = 1.0f - occlusion * (u.strength / static_cast<float>(u.count));
    return vec4(ao, ao, ao, 1.0f);
  }
};

using SsaoFS = SsaoFSFor<false>;
using SsaoOrthoFS = SsaoFSFor<true>;

}  // namespace skinsim::pipeline::shaders
