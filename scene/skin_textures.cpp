#include "scene/skin_textures.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <numbers>

#include "scene/hash_noise.h"
#include "scene/head_shape.h"

namespace skinsim::scene::head {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

float smoothstep(float e0, float e1, float x) {
  const float t = glm::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// Thin grooves: 1 on a line, falling to 0 between lines (a sharpened |cos|).
float grooves(float phase, float sharpness) {
  return std::pow(std::abs(std::cos(phase)), sharpness);
}

struct Texel {
  glm::vec3 albedo;    // sRGB
  float reflectivity;  // linear
  float height_mm;     // surface relief for the normal map (negative = into the skin)
};

Texel paint(const glm::vec3& p, const glm::vec2& texel, int size) {
  const head::Regions r = regions_at(p);
  const glm::vec3 mm = p * 1000.0f;

  // Relief. Pores: pits on a ~2-texel lattice in UV space (periodic across the seam).
  const int pore_cells = std::max(1, size / 2);
  const glm::vec2 pore_uv = texel * (static_cast<float>(pore_cells) / size);
  const float pore =
      std::pow(std::max(0.0f, value_noise_periodic(pore_uv, pore_cells, 11u) - 0.3f) / 0.7f, 2.0f);
  const int fine_cells = std::max(1, size / 6);
  const float fine =
      value_noise_periodic(texel * (static_cast<float>(fine_cells) / size), fine_cells, 12u);
  float h = -0.12f * pore + 0.03f * fine;
  const float warp = fbm(mm * 0.08f, 2, 13u);
  h -= 0.12f * r.forehead * grooves(kPi * (mm.y / 8.0f) + 1.5f * warp, 12.0f);
  const float corner_angle = std::atan2(mm.y - 10.0f, std::abs(mm.x) - 44.0f);
  h -= 0.08f * r.crow_feet * grooves(corner_angle * 9.0f + 2.0f * warp, 16.0f);
  h -= 0.35f * r.nasolabial;
  h -= 0.03f * r.lips * grooves(kPi * mm.x / 1.6f + warp, 6.0f);

  // Albedo (sRGB). Base: the Macbeth ColorChecker "light skin" patch, sRGB (194,150,130).
  glm::vec3 c(0.76f, 0.59f, 0.51f);
  const float blotch = fbm(mm * 0.06f, 3, 21u);      // ~1.5 cm blotches
  const float mottle = fbm(mm * 0.35f, 2, 22u);      // ~3 mm mottling
  c += glm::vec3(0.035f, -0.02f, -0.015f) * blotch;  // redder / paler patches
  c *= 1.0f + 0.035f * mottle;
  const float freckle = smoothstep(0.55f, 0.7f, value_noise(mm * 0.9f, 23u));
  c *= 1.0f - 0.06f * freckle * smoothstep(0.0f, 0.04f, p.z);
  c = glm::mix(c, glm::vec3(0.80f, 0.50f, 0.46f), 0.35f * r.cheeks);
  c = glm::mix(c, glm::vec3(0.62f, 0.47f, 0.46f), 0.15f * r.eye_lids);
  c = glm::mix(c, glm::vec3(0.69f, 0.36f, 0.38f) * (1.0f + 0.05f * mottle), r.lips);
  const float hair = smoothstep(-0.2f, 0.3f, value_noise(mm * glm::vec3(0.4f, 2.5f, 2.5f), 24u));
  c = glm::mix(c, glm::vec3(0.27f, 0.19f, 0.14f), r.brows * (0.55f + 0.45f * hair));
  c *= 1.0f - 0.8f * pore * 0.12f;  // pores read slightly darker

  float refl = 0.45f + 0.35f * r.t_zone + 0.25f * r.lips - 0.35f * r.brows;
  refl *= 1.0f - 0.4f * pore;
  return {glm::clamp(c, 0.0f, 1.0f), glm::clamp(refl, 0.0f, 1.0f), h};
}

}  // namespace

SkinTextures paint_skin_textures(int size) {
  const std::size_t n = static_cast<std::size_t>(size) * size;
  std::vector<glm::vec3> pos(n);
  std::vector<float> height(n);
  SkinTextures t;
  t.albedo_reflectivity = {"skin_albedo_reflectivity", size, size, true, std::vector<glm::vec4>(n)};
  t.normal = {"skin_normal", size, size, false, std::vector<glm::vec4>(n)};
  tbb::parallel_for(tbb::blocked_range<int>(0, size), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      for (int x = 0; x < size; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * size + x;
        const glm::vec2 uv((x + 0.5f) / size, (y + 0.5f) / size);
        pos[i] = surface_point(uv.x, uv.y);
        const Texel tx = paint(pos[i], glm::vec2(x + 0.5f, y + 0.5f), size);
        t.albedo_reflectivity.texels[i] = glm::vec4(tx.albedo, tx.reflectivity);
        height[i] = tx.height_mm;
      }
    }
  });
  // Normals from height differences over the physical texel spacing (mm); u wraps around,
  // v clamps at the crown and the neck.
  tbb::parallel_for(tbb::blocked_range<int>(0, size), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      const int up = std::max(y - 1, 0), down = std::min(y + 1, size - 1);
      for (int x = 0; x < size; ++x) {
        const int left = (x + size - 1) % size, right = (x + 1) % size;
        const auto at = [&](int yy, int xx) { return static_cast<std::size_t>(yy) * size + xx; };
        const float su = std::max(500.0f * glm::length(pos[at(y, right)] - pos[at(y, left)]), 0.2f);
        const float sv = std::max(500.0f * glm::length(pos[at(up, x)] - pos[at(down, x)]), 0.2f);
        const float dh_dt = (height[at(y, right)] - height[at(y, left)]) / (2.0f * su);
        const float dh_db = (height[at(up, x)] - height[at(down, x)]) / (2.0f * sv);
        const glm::vec3 nrm = glm::normalize(glm::vec3(-dh_dt, -dh_db, 1.0f));
        t.normal.texels[at(y, x)] = glm::vec4(nrm * 0.5f + 0.5f, 1.0f);
      }
    }
  });
  return t;
}

Image paint_eye_texture(int size) {
  Image img{"eye_albedo", size, size, true,
            std::vector<glm::vec4>(static_cast<std::size_t>(size) * size)};
  // Angular radii (as fractions of pi from the front pole) of pupil and iris for a 12.5 mm
  // eyeball: pupil ~2 mm, iris ~6 mm.
  constexpr float kPupil = 0.052f, kIris = 0.165f;
  for (int y = 0; y < size; ++y) {
    const float v = (y + 0.5f) / size;
    for (int x = 0; x < size; ++x) {
      const float u = (x + 0.5f) / size;
      const float streaks = value_noise_periodic(glm::vec2(u * 96.0f, v * 30.0f), 96, 31u);
      const glm::vec3 sclera(0.93f, 0.91f, 0.87f);
      const float vein = std::pow(
          1.0f - std::abs(value_noise_periodic(glm::vec2(u * 24.0f, v * 12.0f), 24, 32u)), 24.0f);
      glm::vec3 c = glm::mix(sclera, glm::vec3(0.75f, 0.35f, 0.33f),
                             0.6f * vein * smoothstep(0.25f, 0.5f, v));
      const float t = v / kIris;  // 0 at the pupil centre, 1 at the limbus
      glm::vec3 iris = glm::mix(glm::vec3(0.42f, 0.32f, 0.20f), glm::vec3(0.30f, 0.43f, 0.53f),
                                smoothstep(0.35f, 0.7f, t));
      iris *= 1.0f + 0.25f * streaks;
      iris *= 1.0f - 0.6f * smoothstep(0.85f, 1.0f, t);  // limbal ring
      c = glm::mix(iris, c, smoothstep(kIris - 0.006f, kIris + 0.006f, v));
      c = glm::mix(glm::vec3(0.02f), c, smoothstep(kPupil - 0.004f, kPupil + 0.004f, v));
      img.texels[static_cast<std::size_t>(y) * size + x] =
          glm::vec4(glm::clamp(c, 0.0f, 1.0f), 0.9f);
    }
  }
  return img;
}

}  // namespace skinsim::scene::head
