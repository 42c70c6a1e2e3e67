// The built-in default scene: geometry that is closed and consistent, textures that look
// like skin and a normal map, a camera that frames the skin, determinism and speed.
#include "scene/procedural_head.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "scene/error.h"
#include "scene/head_shape.h"
#include "tests/scene/preview_raster.h"

namespace skinsim::scene {
namespace {

DefaultSceneOptions small_options() {
  DefaultSceneOptions o;
  o.head_triangles = 8000;
  o.texture_size = 128;
  o.eye_texture_size = 32;
  o.environment_size = 8;
  return o;
}

const Scene& default_scene() {
  static const Scene s = make_default_scene({});
  return s;
}

const Mesh& mesh_named(const Scene& s, const std::string& name) {
  for (const Mesh& m : s.meshes) {
    if (m.name == name) return m;
  }
  throw std::runtime_error("no mesh " + name);
}

// Build time is measured by bench/bench_frame (BM_DefaultSceneBuild), not asserted here.
TEST(DefaultScene, BuildsAtDefaultSize) {
  const Scene s = make_default_scene({});
  EXPECT_EQ(s.meshes.size(), 5u);
}

TEST(DefaultScene, HeadTriangleCountFollowsTheOption) {
  for (int target : {2000, 60000, 150000}) {
    DefaultSceneOptions o = small_options();
    o.head_triangles = target;
    const Scene s = make_default_scene(o);
    const double n = static_cast<double>(mesh_named(s, "head").triangle_count());
    EXPECT_NEAR(n / target, 1.0, 0.01) << target;
  }
}

TEST(DefaultScene, MaterialsMeshesAndUnits) {
  const Scene& s = default_scene();
  EXPECT_EQ(s.source, "builtin:default-head");
  EXPECT_FLOAT_EQ(s.units_per_mm, 0.001f);
  std::map<std::string, MaterialKind> kinds;
  for (const Material& m : s.materials) kinds[m.name] = m.kind;
  EXPECT_EQ(kinds.at("skin"), MaterialKind::kSkin);
  EXPECT_EQ(kinds.at("eye"), MaterialKind::kEye);
  EXPECT_EQ(kinds.at("shirt"), MaterialKind::kOther);
  EXPECT_EQ(kinds.at("backdrop"), MaterialKind::kOther);
  EXPECT_EQ(s.materials[mesh_named(s, "head").material].name, "skin");
  EXPECT_EQ(s.materials[mesh_named(s, "eye_left").material].name, "eye");
  EXPECT_EQ(s.materials[mesh_named(s, "eye_right").material].name, "eye");
  const Material& skin = s.materials[mesh_named(s, "head").material];
  ASSERT_GE(skin.base_color_texture, 0);
  ASSERT_GE(skin.normal_texture, 0);
  EXPECT_TRUE(s.images[skin.base_color_texture].srgb);
  EXPECT_FALSE(s.images[skin.normal_texture].srgb);
  EXPECT_EQ(s.images[skin.base_color_texture].width, 1024);
  EXPECT_EQ(s.images[skin.normal_texture].height, 1024);
  EXPECT_EQ(s.environment.size, 64);
  // Real head size: about 0.2-0.3 m crown to chin (plus the neck), 0.14-0.2 m wide.
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (const auto& p : mesh_named(s, "head").positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  EXPECT_GT(hi.x - lo.x, 0.14f);
  EXPECT_LT(hi.x - lo.x, 0.22f);
  EXPECT_GT(hi.y - 0.0f, 0.1f);  // crown above the eyes
}

// Every edge of a closed, consistently oriented mesh appears once in each direction
// (after welding the UV seam); the signed volume of an outward-facing mesh is positive.
void expect_closed_and_outward(const Mesh& m) {
  std::map<std::tuple<float, float, float>, std::uint32_t> weld;
  std::vector<std::uint32_t> id(m.positions.size());
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const auto& p = m.positions[i];
    id[i] =
        weld.try_emplace({p.x, p.y, p.z}, static_cast<std::uint32_t>(weld.size())).first->second;
  }
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  double volume = 0.0;
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = id[m.indices[t + k]], b = id[m.indices[t + (k + 1) % 3]];
      if (a != b) ++directed[{a, b}];
    }
    const glm::vec3 p0 = m.positions[m.indices[t]], p1 = m.positions[m.indices[t + 1]],
                    p2 = m.positions[m.indices[t + 2]];
    volume += glm::dot(p0, glm::cross(p1, p2)) / 6.0;
  }
  std::size_t unmatched = 0;
  for (const auto& [edge, count] : directed) {
    if (count != 1 || !directed.count({edge.second, edge.first})) ++unmatched;
  }
  EXPECT_EQ(unmatched, 0u) << m.name;
  EXPECT_GT(volume, 0.0) << m.name;
}

TEST(DefaultScene, MeshesAreClosedAndFaceOutwards) {
  const Scene s = make_default_scene(small_options());
  for (const char* name : {"head", "eye_left", "eye_right", "shirt"})
    expect_closed_and_outward(mesh_named(s, name));
}

TEST(DefaultScene, NormalsAndTangentsAreOrthonormal) {
  const Scene& s = default_scene();
  for (const Mesh& m : s.meshes) {
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      ASSERT_NEAR(glm::length(m.normals[i]), 1.0f, 1e-4f) << m.name << " " << i;
      ASSERT_NEAR(glm::length(glm::vec3(m.tangents[i])), 1.0f, 1e-4f) << m.name << " " << i;
      ASSERT_NEAR(glm::dot(glm::vec3(m.tangents[i]), m.normals[i]), 0.0f, 1e-4f)
          << m.name << " " << i;
    }
  }
  // On the face, the tangent follows +u (towards +X) and the bitangent points up.
  const Mesh& head = mesh_named(s, "head");
  std::size_t front = 0;
  for (std::size_t i = 0; i < head.positions.size(); ++i) {
    if (head.normals[i].z < 0.95f) continue;
    ++front;
    EXPECT_GT(head.tangents[i].x, 0.8f);
    const glm::vec3 b =
        glm::cross(head.normals[i], glm::vec3(head.tangents[i])) * head.tangents[i].w;
    EXPECT_GT(b.y, 0.8f);
  }
  EXPECT_GT(front, 100u);
}

TEST(DefaultScene, UvSeamIsAtTheBack) {
  const Mesh& head = mesh_named(default_scene(), "head");
  for (std::size_t i = 0; i < head.positions.size(); ++i) {
    if (head.uvs[i].x == 0.0f || head.uvs[i].x == 1.0f) {
      // The crown and neck-cap vertices sit on the axis; others are behind the centre.
      EXPECT_LE(head.positions[i].z, 1e-6f);
    }
  }
}

// Mean of texels whose surface point lies in a region mask > 0.5.
glm::vec4 region_mean(const Image& img, float head::Regions::*field) {
  glm::dvec4 sum(0.0);
  int n = 0;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const glm::vec3 p = head::surface_point((x + 0.5f) / img.width, (y + 0.5f) / img.height);
      if (head::regions_at(p).*field > 0.5f) {
        sum += glm::dvec4(img.texels[y * img.width + x]);
        ++n;
      }
    }
  }
  return n > 0 ? glm::vec4(sum / double(n)) : glm::vec4(-1.0f);
}

TEST(DefaultScene, AlbedoLooksLikeSkin) {
  DefaultSceneOptions o = small_options();
  o.texture_size = 256;
  const Scene s = make_default_scene(o);
  const Image& albedo = s.images[s.materials[0].base_color_texture];
  glm::dvec4 mean(0.0);
  glm::dvec3 lo(1.0), hi(0.0);
  for (const auto& t : albedo.texels) {
    mean += glm::dvec4(t);
    lo = glm::min(lo, glm::dvec3(t));
    hi = glm::max(hi, glm::dvec3(t));
  }
  mean /= double(albedo.texels.size());
  // sRGB skin: red > green > blue, mid-to-light.
  EXPECT_GT(mean.r, mean.g);
  EXPECT_GT(mean.g, mean.b);
  EXPECT_GT(mean.r, 0.6);
  EXPECT_LT(mean.r, 0.9);
  EXPECT_GT(hi.r - lo.r, 0.1);  // not flat: blotches, lips, brows
  // Lips redder than the cheeks' surroundings, brows darker, the T-zone more reflective.
  const glm::vec4 lips = region_mean(albedo, &head::Regions::lips);
  const glm::vec4 brows = region_mean(albedo, &head::Regions::brows);
  const glm::vec4 tzone = region_mean(albedo, &head::Regions::t_zone);
  EXPECT_GT(lips.r / lips.g, mean.r / mean.g + 0.2);
  EXPECT_LT(brows.r + brows.g + brows.b, 0.8f * (mean.r + mean.g + mean.b));
  EXPECT_GT(tzone.a, mean.a + 0.1);
}

TEST(DefaultScene, NormalMapIsUnitAndMostlyFlatWithDetail) {
  DefaultSceneOptions o = small_options();
  o.texture_size = 512;  // pores are sub-millimetre: too small to show at low resolution
  const Scene s = make_default_scene(o);
  const Image& nm = s.images[s.materials[0].normal_texture];
  glm::dvec3 mean(0.0);
  double spread = 0.0;
  for (const auto& t : nm.texels) {
    const glm::vec3 n = glm::vec3(t) * 2.0f - 1.0f;
    ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
    ASSERT_GT(n.z, 0.0f);
    mean += glm::dvec3(n);
    spread += 1.0 - n.z;
  }
  mean /= double(nm.texels.size());
  EXPECT_GT(mean.z, 0.95);
  EXPECT_GT(spread / nm.texels.size(), 1e-4);  // pores and wrinkles are there
}

TEST(DefaultScene, SkinCoversMostOfTheFrame) {
  const Scene& s = default_scene();
  const auto frame = testing::rasterize(s, 256, 192);  // 4:3, like 2048x1536
  const double skin = testing::coverage(s, frame, MaterialKind::kSkin);
  const double eyes = testing::coverage(s, frame, MaterialKind::kEye);
  RecordProperty("skin_coverage", std::to_string(skin));
  EXPECT_GT(skin, 0.5);
  EXPECT_GT(eyes, 0.002);  // both eyes visible
  EXPECT_LT(eyes, 0.05);
}

TEST(DefaultScene, Deterministic) {
  const Scene a = make_default_scene(small_options());
  const Scene b = make_default_scene(small_options());
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  for (std::size_t i = 0; i < a.meshes.size(); ++i) {
    EXPECT_EQ(a.meshes[i].positions, b.meshes[i].positions);
    EXPECT_EQ(a.meshes[i].tangents, b.meshes[i].tangents);
    EXPECT_EQ(a.meshes[i].indices, b.meshes[i].indices);
  }
  for (std::size_t i = 0; i < a.images.size(); ++i)
    EXPECT_EQ(a.images[i].texels, b.images[i].texels);
}

TEST(DefaultScene, RejectsBadOptions) {
  DefaultSceneOptions o = small_options();
  o.head_triangles = 10;
  try {
    make_default_scene(o);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("head_triangles"), std::string::npos);
  }
  o = small_options();
  o.texture_size = 0;
  EXPECT_THROW(make_default_scene(o), SceneError);
}

}  // namespace
}  // namespace skinsim::scene
