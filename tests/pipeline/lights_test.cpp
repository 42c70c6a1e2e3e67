// The frame's light on the emulated GPU (pipeline/frame_lights.h, shaders/lights.h): the
// key light's shadow pass and fetches, the back light, transmission and the framing knobs,
// each checked against the frame without it.
#include "pipeline/shaders/lights.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/glm.hpp>

#include "pipeline/frame_lights.h"
#include "pipeline/lighting.h"
#include "scene/gltf_loader.h"
#include "sim/render_target.h"
#include "sim/shader_io.h"
#include "sim/texture_line_log.h"
#include "tests/pipeline/small_frames.h"
#include "tests/test_paths.h"

namespace skinsim::pipeline {
namespace {

using testing::render;
using testing::skin_draw;
using testing::small_config;
using testing::small_scene;

PipelineConfig with(PipelineConfig c, const std::string& key, const std::string& value) {
  set_config_field(c, key, value);
  return c;
}

const sim::PassCounters& pass_named(const FrameOutput& out, const std::string& name) {
  for (const auto& p : out.passes) {
    if (p.name == name) return p;
  }
  throw std::runtime_error("no pass " + name);
}

double sum_rgb(const sim::RenderTarget& t) {
  double s = 0.0;
  for (const glm::vec4& p : t.pixels) s += p.r + p.g + p.b;
  return s;
}

TEST(Shadows, ADepthOnlyPassDarkensTheFrameAndAddsOneFetch) {
  const PipelineConfig lit = with(small_config("wrap"), "shadows", "off");
  const FrameOutput off = render(lit);
  const FrameOutput on = render(small_config("wrap"));
  EXPECT_EQ(off.passes.size(), 1u);
  ASSERT_EQ(on.passes.size(), 2u);
  const sim::PassCounters& shadow = pass_named(on, "shadow");
  EXPECT_EQ(shadow.fragments_shaded, 0u);  // ISP only
  EXPECT_GT(shadow.fragments_depth_tested, 0u);
  EXPECT_EQ(shadow.depth_store_bytes, 1024u * 1024u * 2u);  // depth16, stored for sampling
  EXPECT_EQ(skin_draw(on).fragment_profile.texture_reads_independent,
            skin_draw(off).fragment_profile.texture_reads_independent + 1);
  EXPECT_LT(sum_rgb(on.frame), 0.99 * sum_rgb(off.frame));  // the nose and jaw shadows
}

TEST(Shadows, ExtraPcfTapsAreDependentFetchesInTheLightPass) {
  const FrameOutput one = render(with(small_config("mobile"), "shadow_taps", "1"));
  const FrameOutput four = render(small_config("mobile"));  // the default: 4
  const sim::OpProfile& a = pass_named(one, "irradiance").draws.at(0).fragment_profile;
  const sim::OpProfile& b = pass_named(four, "irradiance").draws.at(0).fragment_profile;
  EXPECT_EQ(a.texture_reads_independent, 1u);
  EXPECT_EQ(a.texture_reads_dependent, 0u);
  EXPECT_EQ(b.texture_reads_independent, 1u);
  EXPECT_EQ(b.texture_reads_dependent, 3u);
  EXPECT_GT(b.alu_ops(), a.alu_ops());
}

// The steepest stretch of the shadow filter's edge along a straight occluder edge: the
// largest slope, in shadow-map texels per texel, of the visibility's 0.5 contour. The map is
// synthetic, an occluder edge rising 1 texel in 8 (so 0.125 for a smooth edge; nearest
// texels make steps, slope 8 at each), sampled 8 points per texel, as a grazing receiver at
// 2048x1536 sees the default 1024 map (the lip's 5-10 px steps of issue 47); the taps, their
// offsets and the sampler are the config's (FrameLights).
double steepest_shadow_edge(PipelineConfig c) {
  constexpr int kSize = 64, kPerTexel = 8;
  constexpr float kSlope = 1.0f / 8.0f, kEdgeAt = 24.0f;  // texel rows, at column 0
  set_config_field(c, "shadow_map_size", std::to_string(kSize));
  sim::Gpu gpu(sim::GpuConfig{});
  std::vector<sim::PassCounters> passes;
  const FrameLights lights(small_scene(), c, gpu, passes);
  sim::RenderTarget map("edge", kSize, kSize, c.shadow_depth);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const bool occluder = (y + 0.5f) < kEdgeAt + kSlope * (x + 0.5f);
      map.at(x, y) = glm::vec4(occluder ? 0.0f : 1.0f);
    }
  }
  // The synthetic map with the sampler FrameLights gives its own, in the same binding.
  sim::DrawCall draw;
  lights.bind(draw);
  const sim::Texture2D* own = draw.textures.textures[shaders::LightBindings::kShadowMap];
  const sim::Texture2D tex = sim::texture_view(map, own->sampler());
  sim::TextureBindings bindings;
  bindings.textures[shaders::LightBindings::kShadowMap] = &tex;
  sim::TextureLineLog lines;
  sim::TextureCounters counters;
  sim::ExecTexUnit unit(&lines, &counters);
  unit.bind(&bindings);
  const shaders::LightVaryings slots{0, -1};
  const auto visibility = [&](float u, float v) {
    sim::Plane planes[sim::kMaxVaryings] = {};
    planes[0].c = u;
    planes[1].c = v;
    planes[2].c = 0.5f;  // the receiver's depth, between the occluder's and the backdrop's
    const sim::Plane inv_w{1.0f, 0.0f, 0.0f};
    const sim::ExecFragIn in(planes, inv_w, 0.0f, 0.0f, glm::vec2(0.5f), glm::vec2(1.0f));
    return shaders::key_visibility<sim::Exec>(in, unit, lights.uniforms(), slots);
  };
  // The 0.5 contour in each column of sample points, away from the map's sides.
  std::vector<glm::dvec2> edge;
  for (int i = 8 * kPerTexel; i < (kSize - 8) * kPerTexel; ++i) {
    const float u = (i + 0.5f) / (kSize * kPerTexel);
    float previous = visibility(u, 0.0f);
    for (int j = 1; j < kSize * kPerTexel; ++j) {
      const float lit = visibility(u, static_cast<float>(j) / (kSize * kPerTexel));
      if (previous < 0.5f && lit >= 0.5f) {
        const float t = (0.5f - previous) / (lit - previous);
        edge.emplace_back(u * kSize, (j - 1 + t) / kPerTexel);
        break;
      }
      previous = lit;
    }
  }
  EXPECT_EQ(edge.size(), (kSize - 16u) * kPerTexel);  // one crossing in every column
  double steepest = 0.0;
  for (std::size_t i = 1; i < edge.size(); ++i) {
    steepest =
        std::max(steepest, std::abs((edge[i].y - edge[i - 1].y) / (edge[i].x - edge[i - 1].x)));
  }
  return steepest;
}

// Measured: nearest 8 (a step), pcf2x2 with 1 tap 1.78, with 4 taps 0.50, 9 taps 0.33.
TEST(Shadows, TheDefaultFilterFollowsAStraightEdgeWithoutSteps) {
  const PipelineConfig defaults = small_config("wrap");
  EXPECT_GT(steepest_shadow_edge(with(defaults, "shadow_taps", "1")), 1.5);
  EXPECT_LT(steepest_shadow_edge(defaults), 0.6);
}

TEST(Shadows, TintLeavesLightInShadow) {
  const FrameOutput black = render(small_config("wrap"));
  const FrameOutput tinted = render(with(small_config("wrap"), "shadow_tint", "0.3,0.1,0.05"));
  EXPECT_GT(sum_rgb(tinted.frame), sum_rgb(black.frame));
}

TEST(BackLight, EachLightAddsItsReads) {
  const FrameOutput key = render(with(small_config("preintegrated"), "back_light", "0"));
  const FrameOutput both = render(small_config("preintegrated"));
  // Per light: three pre-integrated LUT reads and one BRDF LUT read.
  EXPECT_EQ(skin_draw(both).fragment_profile.texture_reads_dependent,
            skin_draw(key).fragment_profile.texture_reads_dependent + 4);
}

// The built-in head has no thin parts (its ears are relief on a closed surface); the scan's
// ears and eyelids are.
TEST(Transmission, OnlyAddsLightAndMostToRedInThinParts) {
  const std::string path = test_paths::kLeePerrySmith;
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "asset not found: " << path;
  scene::LoadOptions o;
  o.units_per_mm = 0.0353f;
  o.skin_materials = {"all"};
  o.warn = [](const std::string&) {};
  const scene::Scene scan = scene::load_gltf(path, o);
  const GpuScene gs(scan);
  for (const char* technique : {"wrap", "mobile", "burley"}) {
    const auto frame = [&](const char* transmission) {
      PipelineConfig c = with(small_config(technique), "transmission", transmission);
      set_config_field(c, "resolution", "512x384");
      sim::Gpu gpu(sim::GpuConfig{});
      return render_frame(gs, c, gpu);
    };
    const FrameOutput off = frame("off"), on = frame("on");
    glm::dvec3 gain(0.0);
    for (std::size_t i = 0; i < on.frame.pixels.size(); ++i) {
      const glm::vec3 d = glm::vec3(on.frame.pixels[i]) - glm::vec3(off.frame.pixels[i]);
      EXPECT_GE(glm::min(d.r, glm::min(d.g, d.b)), -1.5f / 255.0f) << technique << " pixel " << i;
      gain += glm::dvec3(d);
    }
    EXPECT_GT(gain.r, 0.5) << technique;  // tens of ear and eyelid pixels
    EXPECT_GT(gain.r, 5.0 * gain.b) << technique;
  }
}

TEST(Framing, DistanceShrinksTheSkinAndSwitchesToTheLodShader) {
  const FrameOutput near = render(with(small_config("mobile"), "camera_distance_m", "0.5"));
  const FrameOutput far = render(with(small_config("mobile"), "camera_distance_m", "1"));
  const FrameOutput lod = render(with(small_config("mobile"), "camera_distance_m", "2.5"));
  const auto area = [](const View& v) {
    return static_cast<double>(v.skin_rect.x1 - v.skin_rect.x0) * (v.skin_rect.y1 - v.skin_rect.y0);
  };
  EXPECT_NEAR(far.view.skin_distance / near.view.skin_distance, 2.0, 1e-3);
  // The skin's screen rectangle, clipped by the frame when near: at most a quarter the area.
  EXPECT_LT(area(far.view) / area(near.view), 0.55);
  EXPECT_EQ(near.decisions.at("lod_shader"), 0.0);
  EXPECT_NEAR(far.decisions.at("blur_sigma_texels") / near.decisions.at("blur_sigma_texels"), 0.5,
              1e-3);
  EXPECT_EQ(lod.decisions.at("lod_shader"), 1.0);
}

TEST(Framing, AnglesAreInTheCharactersFrame) {
  PipelineConfig c = small_config("wrap");
  set_config_field(c, "light_azimuth_deg", "0");
  set_config_field(c, "light_elevation_deg", "0");
  const scene::Camera& cam = small_scene().scene().camera;
  const glm::vec3 towards_camera =
      glm::normalize(cam.position - small_scene().skin_bounds().centre());
  const FrameLighting front = frame_lighting(small_scene(), c);
  EXPECT_GT(glm::dot(front.key.direction, towards_camera), 0.95f);
  set_config_field(c, "light_elevation_deg", "89");
  EXPECT_GT(frame_lighting(small_scene(), c).key.direction.y, 0.99f);
  // Yaw orbits the camera at the same distance.
  set_config_field(c, "camera_yaw_deg", "90");
  const scene::Camera yawed = frame_camera(small_scene(), c);
  const glm::vec3 centre = small_scene().skin_bounds().centre();
  EXPECT_NEAR(glm::length(yawed.position - centre), glm::length(cam.position - centre), 1e-4f);
  EXPECT_NEAR(glm::dot(glm::normalize(yawed.position - centre), towards_camera), 0.0f, 0.1f);
}

// A bust orbits its face: --camera-distance places the camera at that distance from the
// measured head's centre and aims at it, not at the skin's box (which the shoulders pull
// down to the chin).
TEST(Framing, CameraDistanceOrbitsAScansHead) {
  const std::string path = test_paths::kLeePerrySmith;
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "asset not found: " << path;
  scene::LoadOptions o;
  o.skin_materials = {"all"};
  o.environment_size = 4;
  o.warn = [](const std::string&) {};
  const scene::Scene scan = scene::load_gltf(path, o);
  ASSERT_TRUE(scan.head);
  const GpuScene gs(scan);
  const PipelineConfig c = with(small_config("wrap"), "camera_distance_m", "0.5");
  const scene::Camera cam = frame_camera(gs, c);
  const glm::vec3 head = scan.head->centre();
  EXPECT_NEAR(glm::length(cam.target - head), 0.0f, 1e-4f);
  EXPECT_NEAR(glm::length(cam.position - head), 500.0f * scan.units_per_mm, 1e-3f);
  EXPECT_GT(cam.target.y, gs.skin_bounds().centre().y + 1.0f);  // above the bust's centre
}

}  // namespace
}  // namespace skinsim::pipeline
