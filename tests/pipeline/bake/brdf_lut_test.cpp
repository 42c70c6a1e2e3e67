#include "pipeline/bake/brdf_lut.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <glm/geometric.hpp>
#include <numbers>

#include "image/image.h"
#include "pipeline/bake/error.h"
#include "pipeline/bake/specular.h"

namespace skinsim::bake {
namespace {

BrdfLutParams small_params() {
  BrdfLutParams p;
  p.width = 16;
  p.height = 64;
  return p;
}

TEST(BrdfLut, MipChainHalvesAndRoughensPerLevel) {
  const BrdfLut lut = bake_brdf_lut(BrdfLutParams{});
  ASSERT_EQ(lut.levels.size(), 8u);  // 128 rows -> 1
  for (std::size_t k = 0; k < lut.levels.size(); ++k) {
    const LutLevel& level = lut.levels[k];
    EXPECT_EQ(level.width, std::max(1, 32 >> k));
    EXPECT_EQ(level.height, 128 >> k);
    EXPECT_EQ(level.texels.size(), static_cast<std::size_t>(level.width) * level.height);
    EXPECT_FLOAT_EQ(level.m1, 0.3f * (1.0f + 0.5f * k));
    EXPECT_FLOAT_EQ(level.m2, 0.6f * (1.0f + 0.5f * k));
  }
  EXPECT_FLOAT_EQ(brdf_lut_lod(roughness_scale_for_level(3)), 3.0f);
}

TEST(BrdfLut, WhiteFurnaceAlbedoIsAtMostOne) {
  // F = 1 and rho_s = 1/pi make each lobe the plain Kelemen BRDF, which must not create energy.
  BrdfLutParams p;
  p.f0 = 1.0f;
  p.rho_s = 1.0f / std::numbers::pi_v<float>;
  p.weight1 = 1.0f;
  p.weight2 = 0.0f;
  for (float m : {0.1f, 0.3f, 0.6f, 1.0f, 2.0f}) {
    for (float v : {1.0f, 0.8f, 0.5f, 0.3f, 0.1f, 0.02f}) {
      const double albedo = directional_reflectance(v, m, m, p).albedo;
      EXPECT_LE(albedo, 1.0 + 1e-3) << "m = " << m << ", N.V = " << v;
      EXPECT_GT(albedo, 0.0) << "m = " << m << ", N.V = " << v;
    }
  }
  // A smooth lobe at normal incidence reflects (nearly) everything.
  EXPECT_NEAR(directional_reflectance(1.0f, 0.1f, 0.1f, p).albedo, 1.0, 0.02);
}

// The dual-lobe KS albedo rho_s * sum_i w_i int P_H,i F / |L + V|^2 N.L dw_L, written out
// here and integrated over light directions (uniform in N.L and azimuth), where the bake
// integrates over half vectors: an independent evaluation of the same integral.
double albedo_over_lights(double v, double m1, double m2, const BrdfLutParams& p) {
  const auto beckmann = [](double c, double m) {
    const double c2 = c * c;
    return std::exp((c2 - 1.0) / (m * m * c2)) / (std::numbers::pi * m * m * c2 * c2);
  };
  const glm::dvec3 view(std::sqrt(1.0 - v * v), 0.0, v);
  constexpr int kCos = 1024, kAzimuth = 1024;
  double sum = 0.0;
  for (int i = 0; i < kCos; ++i) {
    const double n_dot_l = (i + 0.5) / kCos;
    const double sin_l = std::sqrt(1.0 - n_dot_l * n_dot_l);
    for (int j = 0; j < kAzimuth; ++j) {
      const double phi = (j + 0.5) * 2.0 * std::numbers::pi / kAzimuth;
      const glm::dvec3 h = glm::dvec3(sin_l * std::cos(phi), sin_l * std::sin(phi), n_dot_l) + view;
      const glm::dvec3 half = glm::normalize(h);
      const double f = p.f0 + (1.0 - p.f0) * std::pow(1.0 - glm::dot(view, half), 5.0);
      const double d = p.weight1 * beckmann(half.z, m1) + p.weight2 * beckmann(half.z, m2);
      sum += std::numbers::pi * d * f / glm::dot(h, h) * n_dot_l;
    }
  }
  return p.rho_s * sum * 2.0 * std::numbers::pi / (kCos * kAzimuth);
}

TEST(BrdfLut, EnergyChannelIsOneMinusTheIntegratedAlbedo) {
  const BrdfLutParams p = small_params();
  const BrdfLut lut = bake_brdf_lut(p);
  for (int k : {0, 2}) {
    const LutLevel& level = lut.levels[k];
    for (int j : {0, level.height / 4, level.height / 2, level.height - 1}) {
      const double v = (j + 0.5) / level.height;
      const double expected = 1.0 - albedo_over_lights(v, level.m1, level.m2, p);
      // Measured: 3.6e-4 apart in level 0's grazing row (N.V = 0.008), at most 7e-5 elsewhere.
      EXPECT_NEAR(level.at(0, j).w, expected, 1e-3) << "level " << k << ", N.V = " << v;
    }
  }
}

TEST(BrdfLut, EnergyInUnitRangeAndFallsTowardGrazing) {
  const BrdfLut lut = bake_brdf_lut(BrdfLutParams{});
  for (const LutLevel& level : lut.levels) {
    for (const glm::vec4& t : level.texels) {
      ASSERT_GE(t.w, 0.0f);
      ASSERT_LE(t.w, 1.0f);
    }
  }
  // Below N.V ~ 0.8 the Fresnel term dominates and A rises monotonically with N.V. Nearer
  // normal incidence F is flat at F0 while the Kelemen lobe's albedo changes slightly, so A
  // may dip by ~1e-5 there; grazing is still its minimum.
  for (int k = 0; k < 3; ++k) {
    const LutLevel& level = lut.levels[k];
    for (int j = 1; j < level.height; ++j) {
      EXPECT_GT(level.at(0, j).w, level.at(0, 0).w) << "level " << k << " row " << j;
      if ((j + 0.5f) / level.height > 0.8f) continue;
      EXPECT_GT(level.at(0, j).w, level.at(0, j - 1).w) << "level " << k << " row " << j;
    }
  }
}

TEST(BrdfLut, FresnelLimits) {
  const BrdfLut lut = quantize(bake_brdf_lut(BrdfLutParams{}), LutFormat::kRGBA8);
  const LutLevel& level0 = lut.levels[0];
  // At normal incidence the lobe-averaged Fresnel is F0 (within 8-bit quantisation).
  EXPECT_NEAR(level0.at(0, level0.height - 1).z, 0.028f, 1.0f / 255.0f);
  // It grows toward grazing.
  for (int j = 1; j < level0.height; ++j) EXPECT_LE(level0.at(0, j).z, level0.at(0, j - 1).z);
  // For smooth lobes H stays near N, so at grazing V.H -> 0 and Schlick's F -> 1.
  BrdfLutParams smooth;
  smooth.m1 = smooth.m2 = 0.02f;
  smooth.albedo_theta_samples = 256;
  EXPECT_GT(directional_reflectance(0.002f, 0.02f, 0.02f, smooth).fresnel, 0.9);
  EXPECT_NEAR(directional_reflectance(1.0f, 0.02f, 0.02f, smooth).fresnel, 0.028, 1e-4);
}

// At N.H = 1, H = N and V.H = N.V for every azimuth, and D(1) = 1 / (pi m^2): the response
// is F(N.V) / (4 m^2 N.V^2) in closed form (measured: at most 2.4e-7 apart, relative).
TEST(BrdfLut, LobeResponseAtThePeakIsTheClosedForm) {
  const float m = 0.3f, f0 = 0.028f;
  for (float v : {0.2f, 0.5f, 0.9f}) {
    const double f = f0 + (1.0 - f0) * std::pow(1.0 - v, 5.0);
    const double expected = f / (4.0 * m * m * v * v);
    EXPECT_NEAR(lut_lobe_response(1.0f, v, m, f0, 64), expected, 1e-6 * expected) << "N.V = " << v;
  }
}

TEST(BrdfLut, LobeResponseIsTheAzimuthalAverageOfKsSkinSpecular) {
  // Independent evaluation with vectors: for N.H = u, N.V = v, average
  // ks_skin_specular / (rho_s N.L) over the azimuths of H that light the surface.
  const glm::vec3 n(0.0f, 0.0f, 1.0f);
  const float m = 0.3f;
  for (float u : {0.7f, 0.9f, 0.98f}) {
    for (float v : {0.3f, 0.6f, 0.95f}) {
      const glm::vec3 view(std::sqrt(1.0f - v * v), 0.0f, v);
      double sum = 0.0;
      int valid = 0;
      const int samples = 4096;
      for (int j = 0; j < samples; ++j) {
        const float phi = (j + 0.5f) * std::numbers::pi_v<float> / samples;
        const float s = std::sqrt(1.0f - u * u);
        const glm::vec3 h(s * std::cos(phi), s * std::sin(phi), u);
        const glm::vec3 l = 2.0f * glm::dot(view, h) * h - view;
        if (glm::dot(view, h) <= 0.0f || glm::dot(n, l) <= 0.0f) continue;
        sum += ks_skin_specular(n, l, view, m, 1.0f) / glm::dot(n, l);
        ++valid;
      }
      const double expected = valid == 0 ? 0.0 : sum / valid;
      EXPECT_NEAR(lut_lobe_response(u, v, m, 0.028f, samples), expected, 2e-3 * expected + 1e-6)
          << "u = " << u << ", v = " << v;
    }
  }
}

TEST(BrdfLut, SpecularEncodingRoundTrips) {
  for (float s : {1e-3f, 0.08f, 1.0f, 24.0f, 64.0f}) {
    EXPECT_NEAR(decode_specular_lobe(encode_specular_lobe(s)), s, 1e-5f * s) << s;
  }
  EXPECT_EQ(encode_specular_lobe(1000.0f), 1.0f);
  EXPECT_EQ(encode_specular_lobe(0.0f), 0.0f);
}

// Bake time is measured by bench/bench_frame (BM_BrdfLutBake), not asserted here.
TEST(BrdfLut, BakesAtEverySize) {
  for (int scale : {1, 2, 4, 8, 16}) {
    BrdfLutParams p;
    p.width = 8 * scale;
    p.height = 32 * scale;
    const BrdfLut lut = bake_brdf_lut(p);
    EXPECT_EQ(lut.levels[0].width, p.width);
    EXPECT_EQ(lut.levels[0].height, p.height);
  }
}

TEST(BrdfLut, SameBitsForAnyThreadCount) {
  const BrdfLutParams p = small_params();
  BrdfLut single;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    single = bake_brdf_lut(p);
  }
  const BrdfLut parallel = bake_brdf_lut(p);
  ASSERT_EQ(single.levels.size(), parallel.levels.size());
  for (std::size_t k = 0; k < single.levels.size(); ++k) {
    const auto& a = single.levels[k].texels;
    const auto& b = parallel.levels[k].texels;
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::vec4)), 0) << "level " << k;
  }
}

TEST(BrdfLut, QuantizeRoundsToTheFormat) {
  const BrdfLut lut = bake_brdf_lut(small_params());
  const BrdfLut rgba8 = quantize(lut, LutFormat::kRGBA8);
  const BrdfLut rgba16f = quantize(lut, LutFormat::kRGBA16F);
  for (std::size_t i = 0; i < lut.levels[0].texels.size(); ++i) {
    for (int c = 0; c < 4; ++c) {
      const float original = lut.levels[0].texels[i][c];
      const float eight = rgba8.levels[0].texels[i][c];
      EXPECT_LE(std::abs(eight - original), 0.5f / 255.0f + 1e-7f);
      EXPECT_FLOAT_EQ(std::round(eight * 255.0f), eight * 255.0f);
      const float half = rgba16f.levels[0].texels[i][c];
      // Half a unit in the last place: 2^-11 relative, 2^-25 absolute among subnormals.
      EXPECT_LE(std::abs(half - original),
                std::max(std::ldexp(std::abs(original), -11), std::ldexp(1.0f, -25)));
    }
  }
}

TEST(BrdfLut, BadParametersNameTheField) {
  BrdfLutParams p;
  p.m2 = -1.0f;
  try {
    bake_brdf_lut(p);
    FAIL() << "negative roughness accepted";
  } catch (const BakeError& e) {
    EXPECT_NE(std::string(e.what()).find("m2"), std::string::npos) << e.what();
  }
  p = BrdfLutParams{};
  p.width = 0;
  EXPECT_THROW(bake_brdf_lut(p), BakeError);
  p = BrdfLutParams{};
  p.f0 = 1.5f;
  EXPECT_THROW(bake_brdf_lut(p), BakeError);
  p = BrdfLutParams{};
  p.weight1 = p.weight2 = 0.0f;
  EXPECT_THROW(bake_brdf_lut(p), BakeError);
}

TEST(BrdfLut, WritesAPngOfEachLevel) {
  const BrdfLut lut = bake_brdf_lut(small_params());
  const auto path = std::filesystem::temp_directory_path() /
                    ("skinsim_brdf_lut_" + std::to_string(::getpid()) + ".png");
  write_lut_png(lut, path, 1);
  const image::Image image = image::load_png(path);
  std::filesystem::remove(path);
  EXPECT_EQ(image.width, 8);
  EXPECT_EQ(image.height, 32);
  EXPECT_NEAR(image.at(7, 31).b, lut.levels[1].at(7, 31).z, 0.5f / 255.0f + 1e-6f);
  EXPECT_THROW(write_lut_png(lut, path, 99), BakeError);
}

}  // namespace
}  // namespace skinsim::bake
