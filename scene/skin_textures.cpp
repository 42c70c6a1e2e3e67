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

// Thin grooves: 1 on a line, falling to 0 between lines: cos^(2^k), a sharpened |cos|.
float grooves(float phase, int squarings) {
  float g = std::cos(phase);
  for (int i = 0; i < squarings; ++i) g *= g;
  return g;
}

struct Texel {
  glm::vec3 albedo;    // sRGB
  float reflectivity;  // linear
  float height_mm;     // surface relief for the normal map (negative = into the skin)
};

// The smooth inputs of the painter: the surface point, its region masks and the
// centimetre-scale blotches. They vary over millimetres, so they are evaluated on a grid
// every kCoarseStep texels and interpolated bilinearly, which saves most of the work.
constexpr int kCoarseStep = 4;

struct Smooth {
  glm::vec3 p{0.0f};
  head::Regions r;
  float blotch = 0.0f;
};

Smooth mix(const Smooth& a, const Smooth& b, float t) {
  const auto m = [t](float x, float y) { return x + (y - x) * t; };
  Smooth o;
  o.p = glm::mix(a.p, b.p, t);
  o.r = {m(a.r.lips, b.r.lips),           m(a.r.brows, b.r.brows),
         m(a.r.t_zone, b.r.t_zone),       m(a.r.cheeks, b.r.cheeks),
         m(a.r.eye_lids, b.r.eye_lids),   m(a.r.forehead, b.r.forehead),
         m(a.r.crow_feet, b.r.crow_feet), m(a.r.nasolabial, b.r.nasolabial)};
  o.blotch = m(a.blotch, b.blotch);
  return o;
}

Smooth smooth_at(float u, float v) {
  Smooth s;
  s.p = surface_point(u, v);
  s.r = regions_at(s.p);
  s.blotch = fbm(s.p * 60.0f, 3, 21u);  // ~1.5 cm blotches
  return s;
}

// Grid samples at u = i * step / size, v = j * step / size (one extra row and column past
// the last texel centre; u is periodic in surface_point, v extends the neck).
class SmoothGrid {
 public:
  explicit SmoothGrid(int size) : size_(size), cols_(size / kCoarseStep + 2), rows_(cols_) {
    samples_.resize(static_cast<std::size_t>(cols_) * rows_);
    tbb::parallel_for(tbb::blocked_range<int>(0, rows_), [&](const tbb::blocked_range<int>& rr) {
      for (int j = rr.begin(); j < rr.end(); ++j) {
        for (int i = 0; i < cols_; ++i) {
          samples_[static_cast<std::size_t>(j) * cols_ + i] =
              smooth_at(static_cast<float>(i * kCoarseStep) / size_,
                        static_cast<float>(j * kCoarseStep) / size_);
        }
      }
    });
  }

  Smooth at_texel(int x, int y) const {
    const float fx = (x + 0.5f) / kCoarseStep, fy = (y + 0.5f) / kCoarseStep;
    const int i = std::min(static_cast<int>(fx), cols_ - 2);
    const int j = std::min(static_cast<int>(fy), rows_ - 2);
    const auto s = [&](int ii, int jj) {
      return samples_[static_cast<std::size_t>(jj) * cols_ + ii];
    };
    return mix(mix(s(i, j), s(i + 1, j), fx - i), mix(s(i, j + 1), s(i + 1, j + 1), fx - i),
               fy - j);
  }

 private:
  int size_, cols_, rows_;
  std::vector<Smooth> samples_;
};

Texel paint(const Smooth& smooth, const glm::vec2& texel, int size) {
  const glm::vec3& p = smooth.p;
  const head::Regions& r = smooth.r;
  const glm::vec3 mm = p * 1000.0f;

  // Relief. Pores: pits on a ~2-texel lattice in UV space (periodic across the seam).
  const int pore_cells = std::max(1, size / 2);
  const glm::vec2 pore_uv = texel * (static_cast<float>(pore_cells) / size);
  const float pit = std::max(0.0f, value_noise_periodic(pore_uv, pore_cells, 11u) - 0.3f) / 0.7f;
  const float pore = pit * pit;
  const int fine_cells = std::max(1, size / 6);
  const float fine =
      value_noise_periodic(texel * (static_cast<float>(fine_cells) / size), fine_cells, 12u);
  float h = -0.12f * pore + 0.03f * fine;
  h -= 0.35f * r.nasolabial;
  // Wrinkles only where their masks are non-zero (most texels skip the noise).
  if (r.forehead + r.crow_feet + r.lips > 1e-4f) {
    const float warp = fbm(mm * 0.08f, 2, 13u);
    h -= 0.12f * r.forehead * grooves(kPi * (mm.y / 8.0f) + 1.5f * warp, 3);
    const float corner_angle = std::atan2(mm.y - 10.0f, std::abs(mm.x) - 44.0f);
    h -= 0.08f * r.crow_feet * grooves(corner_angle * 9.0f + 2.0f * warp, 3);
    h -= 0.03f * r.lips * grooves(kPi * mm.x / 1.6f + warp, 2);
  }

  // Albedo (sRGB). Base: the Macbeth ColorChecker "light skin" patch, sRGB (194,150,130).
  glm::vec3 c(0.76f, 0.59f, 0.51f);
  const float mottle = fbm(mm * 0.35f, 2, 22u);             // ~3 mm mottling
  c += glm::vec3(0.035f, -0.02f, -0.015f) * smooth.blotch;  // redder / paler patches
  c *= 1.0f + 0.035f * mottle;
  if (p.z > 0.0f) {  // freckles on the face only
    const float freckle = smoothstep(0.55f, 0.7f, value_noise(mm * 0.9f, 23u));
    c *= 1.0f - 0.06f * freckle * smoothstep(0.0f, 0.04f, p.z);
  }
  c = glm::mix(c, glm::vec3(0.80f, 0.50f, 0.46f), 0.35f * r.cheeks);
  c = glm::mix(c, glm::vec3(0.62f, 0.47f, 0.46f), 0.15f * r.eye_lids);
  c = glm::mix(c, glm::vec3(0.69f, 0.36f, 0.38f) * (1.0f + 0.05f * mottle), r.lips);
  if (r.brows > 1e-4f) {
    const float hair = smoothstep(-0.2f, 0.3f, value_noise(mm * glm::vec3(0.4f, 2.5f, 2.5f), 24u));
    c = glm::mix(c, glm::vec3(0.27f, 0.19f, 0.14f), r.brows * (0.55f + 0.45f * hair));
  }
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
  const SmoothGrid grid(size);
  SkinTextures t;
  t.albedo_reflectivity = {"skin_albedo_reflectivity", size, size, true, std::vector<glm::vec4>(n)};
  t.normal = {"skin_normal", size, size, false, std::vector<glm::vec4>(n)};
  tbb::parallel_for(tbb::blocked_range<int>(0, size), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      for (int x = 0; x < size; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * size + x;
        const Smooth smooth = grid.at_texel(x, y);
        pos[i] = smooth.p;
        const Texel tx = paint(smooth, glm::vec2(x + 0.5f, y + 0.5f), size);
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
