// The reference's ambient visibility (pipeline/reference/ambient_visibility.h): the share of
// a point's cosine-weighted hemisphere that the character leaves open, against the view
// factor of a wall, and what it does to the reference's frame in a crease.
#include "pipeline/reference/ambient_visibility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "pipeline/gpu_scene.h"
#include "pipeline/reference/reference.h"
#include "scene/head_mesh.h"
#include "util/srgb.h"

namespace skinsim::pipeline::reference {
namespace {

constexpr float kOffset = 0.05f;  // the reference's 0.05 mm, in the scene's mm

// A 200 mm square floor of skin facing +z (units: mm), lit by the ambient alone, seen from
// 500 mm above; with a wall `height` mm tall standing on it along x = 0 (`wall_kind`:
// skin, or "other" as a backdrop), 10 m long so that it is an infinite strip for the
// floor's middle. The environment is `plus_x` on the cube's +X face, `rest` elsewhere.
scene::Scene crease(float height, scene::MaterialKind wall_kind, glm::vec4 plus_x = glm::vec4(0.2f),
                    glm::vec4 rest = glm::vec4(0.2f)) {
  scene::Scene s;
  s.source = "test:crease";
  for (const scene::MaterialKind kind : {scene::MaterialKind::kSkin, wall_kind}) {
    scene::Material m;
    m.name = kind == scene::MaterialKind::kSkin ? "skin" : "backdrop";
    m.kind = kind;
    m.base_color_factor = glm::vec4(0.6f, 0.6f, 0.6f, 1.0f);
    m.reflectivity = 1.0f;
    s.materials.push_back(m);
  }
  s.meshes.push_back(scene::head::make_wall("floor", 0.0f, -100.0f, 100.0f, -100.0f, 100.0f));
  s.meshes.back().material = 0;
  if (height > 0.0f) {
    // A wall in the plane z = 0, turned upright: (x, y, z) -> (z, x, y).
    scene::Mesh wall = scene::head::make_wall("wall", 0.0f, -5000.0f, 5000.0f, 0.0f, height);
    const auto upright = [](const glm::vec3& v) { return glm::vec3(v.z, v.x, v.y); };
    for (glm::vec3& v : wall.positions) v = upright(v);
    for (glm::vec3& n : wall.normals) n = upright(n);
    for (glm::vec4& t : wall.tangents) t = glm::vec4(upright(glm::vec3(t)), t.w);
    wall.material = 1;
    s.meshes.push_back(wall);
  }
  s.camera.position = {0, 0, 500};
  s.camera.target = {0, 0, 0};
  s.camera.yfov_radians = 0.4f;
  s.camera.znear = 50.0f;
  s.camera.zfar = 2000.0f;
  s.key_light.direction = {0, 0, 1};
  s.key_light.radiance = glm::vec3(0.0f);  // the ambient alone
  s.ambient = glm::vec3(0.3f);
  s.environment.size = 1;
  for (int f = 0; f < 6; ++f) s.environment.faces[f].assign(1, f == 0 ? plus_x : rest);
  s.units_per_mm = 1.0f;
  return s;
}

// A point on the floor `d` mm from the wall (negative: on its -x side).
AmbientVisibility at_floor(const AmbientRays& rays, float d, int x, int y) {
  return rays.at(glm::vec3(d, 0.0f, kOffset), glm::vec3(0, 0, 1), x, y, kOffset);
}

TEST(AmbientVisibility, AnOpenSurfaceSeesEverything) {
  const scene::Scene s = crease(0.0f, scene::MaterialKind::kSkin);
  const GpuScene gs(s);
  const AmbientRays rays(gs);
  for (int x = 0; x < 16; ++x) {
    const AmbientVisibility v = at_floor(rays, 10.0f, x, 3 * x);
    EXPECT_EQ(v.ambient, 1.0f);
    EXPECT_EQ(v.environment, glm::vec3(1.0f));
  }
}

// The view factor from a floor element to an infinite strip of height H at distance d is
// (1 - d / sqrt(d^2 + H^2)) / 2 (the crossed-strings rule): the open share is the rest.
TEST(AmbientVisibility, TheOpenShareIsOneMinusTheWallsViewFactor) {
  const float height = 50.0f;
  const scene::Scene s = crease(height, scene::MaterialKind::kSkin);
  const GpuScene gs(s);
  const AmbientRays rays(gs);
  for (const float d : {0.5f, 10.0f, 25.0f, 50.0f, 150.0f}) {
    const float expected = 1.0f - 0.5f * (1.0f - d / std::sqrt(d * d + height * height));
    float sum = 0.0f;
    constexpr int kPixels = 64;
    for (int i = 0; i < kPixels; ++i) {
      const AmbientVisibility v = at_floor(rays, d, i % 8, i / 8);
      // One pixel's 32 stratified rays: within three strata of the exact share (measured:
      // up to 2.7).
      EXPECT_NEAR(v.ambient, expected, 3.0f / AmbientRays::kRays) << "d " << d << ", pixel " << i;
      // A uniform environment is dimmed as the ambient.
      EXPECT_NEAR(v.environment.r, v.ambient, 1e-6f);
      sum += v.ambient;
    }
    EXPECT_NEAR(sum / kPixels, expected, 0.01f) << "d " << d;  // neighbours' patterns differ
  }
}

// Each ray looks the environment up in its direction: a wall hides the light of the
// directions it stands in, not a share of every direction's.
TEST(AmbientVisibility, TheEnvironmentIsDimmedByWhatTheWallHides) {
  const scene::Scene s =
      crease(1000.0f, scene::MaterialKind::kSkin, glm::vec4(1.0f), glm::vec4(0.0f));
  const GpuScene gs(s);
  const AmbientRays rays(gs);
  for (int i = 0; i < 16; ++i) {
    const AmbientVisibility facing = at_floor(rays, -1.0f, i, 2 * i);  // the wall hides +x
    const AmbientVisibility behind = at_floor(rays, 1.0f, i, 2 * i);   // it hides -x
    EXPECT_NEAR(facing.ambient, 0.5f, 2.0f / AmbientRays::kRays);
    EXPECT_NEAR(behind.ambient, 0.5f, 2.0f / AmbientRays::kRays);
    EXPECT_EQ(facing.environment, glm::vec3(0.0f));
    EXPECT_EQ(behind.environment, glm::vec3(1.0f));
  }
}

// The backdrop and the shirt are part of the environment, not of the character.
TEST(AmbientVisibility, OnlyTheCharacterHidesTheAmbient) {
  const scene::Scene s = crease(50.0f, scene::MaterialKind::kOther);
  const GpuScene gs(s);
  const AmbientRays rays(gs);
  EXPECT_EQ(at_floor(rays, 1.0f, 5, 7).ambient, 1.0f);
}

TEST(AmbientVisibility, APixelsPatternIsFixedAndItsNeighboursDiffer) {
  const scene::Scene s = crease(50.0f, scene::MaterialKind::kSkin);
  const GpuScene gs(s);
  const AmbientRays rays(gs);
  const float first = at_floor(rays, 20.0f, 9, 4).ambient;
  EXPECT_EQ(at_floor(rays, 20.0f, 9, 4).ambient, first);
  int differ = 0;
  for (int x = 10; x < 19; ++x) differ += at_floor(rays, 20.0f, x, 4).ambient != first ? 1 : 0;
  EXPECT_GT(differ, 0);
}

// In the reference's frame the floor darkens towards the wall as the open share falls, and
// the frame has the same bits for any thread count. (Before the ambient's visibility was
// cast, the floor was as bright at the wall as far from it.)
TEST(AmbientVisibility, TheReferenceDarkensACreaseForAnyThreadCount) {
  const float height = 20.0f;
  const scene::Scene s = crease(height, scene::MaterialKind::kSkin);
  const GpuScene gs(s);
  PipelineConfig c;
  c.width = 160;
  c.height = 120;
  const ReferenceFrame one = render_reference(gs, c, 1);
  const ReferenceFrame three = render_reference(gs, c, 3);
  ASSERT_EQ(one.frame.width, three.frame.width);
  for (int y = 0; y < c.height; ++y) {
    for (int x = 0; x < c.width; ++x) ASSERT_EQ(one.frame.at(x, y), three.frame.at(x, y));
  }
  // The row through the middle: linear light, averaged over 9 rows against the noise.
  const auto light = [&](int x) {
    float sum = 0.0f;
    for (int y = c.height / 2 - 4; y <= c.height / 2 + 4; ++y) {
      sum += srgb_decode(one.frame.at(x, y).g);
    }
    return sum / 9.0f;
  };
  const float mm_per_pixel = 2.0f * 500.0f * std::tan(0.2f) / c.height;
  const int far = c.width / 2 + 50;  // 85 mm from the wall (the floor ends at 100): 97% open
  for (const int x : {c.width / 2 + 2, c.width / 2 + 6, c.width / 2 + 12}) {
    const float d = (static_cast<float>(x) + 0.5f - c.width / 2.0f) * mm_per_pixel;
    const auto open = [&](float dd) {
      return 1.0f - 0.5f * (1.0f - dd / std::sqrt(dd * dd + height * height));
    };
    const float far_d = (static_cast<float>(far) + 0.5f - c.width / 2.0f) * mm_per_pixel;
    EXPECT_NEAR(light(x) / light(far), open(d) / open(far_d), 0.05f) << "x " << x << ", d " << d;
  }
}

}  // namespace
}  // namespace skinsim::pipeline::reference
