// What the glTF loader reads from valid files: geometry in world space, generated
// attributes, materials and images, camera, light; and the real LeePerrySmith scan.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/gtc/constants.hpp>

#include "scene/bounds.h"
#include "scene/gltf_loader.h"
#include "tests/scene/gltf_fixture.h"
#include "tests/test_paths.h"

namespace skinsim::scene {
namespace {

using testing::GltfFixture;

LoadOptions quiet(std::vector<std::string>* warnings = nullptr) {
  LoadOptions o;
  o.warn = [warnings](const std::string& w) {
    if (warnings) warnings->push_back(w);
  };
  o.environment_size = 4;
  return o;
}

void expect_near(const glm::vec3& a, const glm::vec3& b, float tol = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

glm::vec3 face_normal(const Mesh& m, std::size_t t) {
  const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                  c = m.positions[m.indices[3 * t + 2]];
  return glm::normalize(glm::cross(b - a, c - a));
}

TEST(GltfLoad, QuadWithoutNormalsGetsGeneratedAttributes) {
  GltfFixture f("quad_generated");
  f.add_quad_mesh(false, true);
  const Scene s = load_gltf(f.write_gltf("quad"), quiet());
  ASSERT_EQ(s.meshes.size(), 1u);
  const Mesh& m = s.meshes[0];
  EXPECT_EQ(m.triangle_count(), 2u);
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    expect_near(m.normals[i], {0, 0, 1});
    // UVs: u grows with +x, v grows downwards with -y, so T = +X and B (image up) = +Y.
    expect_near(glm::vec3(m.tangents[i]), {1, 0, 0});
    EXPECT_EQ(m.tangents[i].w, 1.0f);
  }
  EXPECT_FLOAT_EQ(s.units_per_mm, 0.001f);
  EXPECT_EQ(s.materials.size(), 1u);  // glTF's default material
  EXPECT_EQ(s.materials[0].kind, MaterialKind::kOther);
}

// Skins are not played (docs/sequences.md): the loader says so rather than draw the bind pose
// silently.
TEST(GltfLoad, ASkinnedMeshIsDrawnInItsBindPoseWithAWarning) {
  GltfFixture f("skinned");
  f.add_quad_mesh(true, true);  // node 0
  f.json()["nodes"].push_back({{"name", "root_joint"}});
  f.json()["skins"] = {{{"joints", {1}}}};
  f.json()["nodes"][0]["skin"] = 0;
  std::vector<std::string> warnings;
  const Scene s = load_gltf(f.write_glb("scene"), quiet(&warnings));
  ASSERT_EQ(s.meshes.size(), 1u);
  const auto skinned = std::find_if(warnings.begin(), warnings.end(), [](const std::string& w) {
    return w.find("nodes[0] is skinned (skins[0])") != std::string::npos;
  });
  ASSERT_NE(skinned, warnings.end());
  EXPECT_NE(skinned->find("bind pose"), std::string::npos) << *skinned;
}

TEST(GltfLoad, MissingUvsGetPlanarFallback) {
  GltfFixture f("quad_no_uv");
  f.add_quad_mesh(true, false);
  const Scene s = load_gltf(f.write_glb("quad"), quiet());
  const Mesh& m = s.meshes[0];
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    EXPECT_FLOAT_EQ(m.uvs[i].x, m.positions[i].x);
    EXPECT_FLOAT_EQ(m.uvs[i].y, 1.0f - m.positions[i].y);
  }
}

TEST(GltfLoad, NodeHierarchyIsAppliedToPositionsNormalsTangents) {
  GltfFixture f("hierarchy");
  f.add_quad_mesh(true, true);  // node 0
  // Parent: translate (1, 2, 3); child (node 0): rotate 90 degrees about +Y, scale 2.
  f.json()["nodes"].push_back({{"translation", {1, 2, 3}}, {"children", {0}}});
  f.json()["scenes"][0]["nodes"] = {1};
  const float h = std::sqrt(0.5f);
  f.json()["nodes"][0]["rotation"] = {0, h, 0, h};
  f.json()["nodes"][0]["scale"] = {2, 2, 2};
  const Scene s = load_gltf(f.write_glb("scene"), quiet());
  const Mesh& m = s.meshes[0];
  // Local (1, 0, 0) -> scaled (2, 0, 0) -> rotated about Y to (0, 0, -2) -> + (1, 2, 3).
  expect_near(m.positions[1], {1, 2, 1});
  expect_near(m.positions[2], {1, 4, 3});
  expect_near(m.normals[0], {1, 0, 0});  // +Z rotated about +Y
  expect_near(glm::vec3(m.tangents[0]), {0, 0, -1});
  EXPECT_GT(glm::dot(face_normal(m, 0), m.normals[0]), 0.99f);
}

TEST(GltfLoad, MatrixTransformAndMirroringKeepFrontFaces) {
  GltfFixture f("mirror");
  f.add_quad_mesh(true, true);
  // Column-major matrix mirroring x and translating by (0, 0, 5).
  f.json()["nodes"][0]["matrix"] = {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1};
  const Scene s = load_gltf(f.write_glb("scene"), quiet());
  const Mesh& m = s.meshes[0];
  expect_near(m.positions[1], {-1, 0, 5});
  expect_near(m.normals[1], {0, 0, 1});
  // Winding flipped so the geometric normal still agrees with the shading normal.
  EXPECT_GT(glm::dot(face_normal(m, 0), m.normals[0]), 0.99f);
  EXPECT_GT(glm::dot(face_normal(m, 1), m.normals[0]), 0.99f);
  // The tangent follows the mirrored +u (now -X); the bitangent sign flips.
  expect_near(glm::vec3(m.tangents[0]), {-1, 0, 0});
  EXPECT_EQ(m.tangents[0].w, -1.0f);
}

TEST(GltfLoad, TriangleStripAndFanBecomeLists) {
  for (int mode : {5, 6}) {
    GltfFixture f(mode == 5 ? "strip" : "fan");
    f.add_quad_mesh(true, true);
    auto& prim = f.json()["meshes"][0]["primitives"][0];
    prim.erase("indices");
    prim["mode"] = mode;
    const Scene s = load_gltf(f.write_glb("scene"), quiet());
    const Mesh& m = s.meshes[0];
    ASSERT_EQ(m.triangle_count(), 2u);
    for (std::size_t t = 0; t < 2; ++t) {
      // Strip (0,1,2),(2,1,3) faces +Z; fan (0,1,2),(0,2,3) has a back-facing second one.
      const float expected = mode == 5 || t == 0 ? 1.0f : -1.0f;
      EXPECT_NEAR(face_normal(m, t).z, expected, 1e-5f) << "mode " << mode << " triangle " << t;
    }
  }
}

TEST(GltfLoad, PointsPrimitiveSkippedWithWarning) {
  GltfFixture f("points_skipped");
  f.add_quad_mesh(true, true);
  auto prim = f.json()["meshes"][0]["primitives"][0];
  prim["mode"] = 0;
  f.json()["meshes"][0]["primitives"].push_back(prim);
  std::vector<std::string> warnings;
  const Scene s = load_gltf(f.write_glb("scene"), quiet(&warnings));
  EXPECT_EQ(s.meshes.size(), 1u);
  ASSERT_GE(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("primitives[1]"), std::string::npos);
}

// A scale past float's range is not "zero scale": the warning says what it is.
TEST(GltfLoad, OverflowingNodeScaleIsNamedAsSuch) {
  GltfFixture f("overflowing_scale");
  f.add_quad_mesh(true, true);
  f.add_quad_mesh(true, true);
  f.json()["nodes"][1]["scale"] = {1e20, 1e20, 1e20};
  std::vector<std::string> warnings;
  const Scene s = load_gltf(f.write_glb("scene"), quiet(&warnings));
  EXPECT_EQ(s.meshes.size(), 1u);
  bool named = false;
  for (const std::string& w : warnings) {
    EXPECT_EQ(w.find("zero scale"), std::string::npos) << w;
    named = named || w.find("more than a float holds") != std::string::npos;
  }
  EXPECT_TRUE(named);
}

// The 1 x 1 quad as a skin material: warnings for an implausible head size (with the
// --units-per-mm that would make it 225 mm, or, with none given, sized so) and for a
// material with no textures.
struct SizeCase {
  float units_per_mm;
  bool expect_size_warning;
};

class HeadSizeWarning : public ::testing::TestWithParam<SizeCase> {};

TEST_P(HeadSizeWarning, WarnsOutsidePlausibleHeadHeights) {
  GltfFixture f("head_size");
  f.add_quad_mesh(true, true);
  f.json()["materials"] = {{{"name", "skin"}}};
  f.json()["meshes"][0]["primitives"][0]["material"] = 0;
  std::vector<std::string> warnings;
  LoadOptions o = quiet(&warnings);
  o.units_per_mm = GetParam().units_per_mm;
  load_gltf(f.write_glb("scene"), o);
  bool size_warned = false, untextured_warned = false;
  for (const std::string& w : warnings) {
    if (w.find("1 units tall") != std::string::npos) {
      size_warned = true;
      // 1 / 225: suggested for a given scale, taken without one (a quad has no face, so its
      // box height stands for the head's).
      EXPECT_NE(w.find(GetParam().units_per_mm > 0.0f ? "--units-per-mm 0.00444" : "no head found"),
                std::string::npos)
          << w;
    }
    if (w.find("material 'skin' has no textures") != std::string::npos) untextured_warned = true;
  }
  EXPECT_EQ(size_warned, GetParam().expect_size_warning);
  EXPECT_TRUE(untextured_warned);
}

INSTANTIATE_TEST_SUITE_P(Units, HeadSizeWarning,
                         ::testing::Values(SizeCase{0.0f, true},       // metres: 1000 mm
                                           SizeCase{0.02f, true},      // 50 mm
                                           SizeCase{0.0044f, false},   // 227 mm
                                           SizeCase{0.008f, false}));  // 125 mm

TEST(GltfLoad, SparseAccessorOverridesValues) {
  GltfFixture f("sparse");
  f.add_quad_mesh(true, true);
  const std::uint16_t idx[2] = {3, 0};
  const float val[6] = {5, 5, 0, -1, -1, 0};
  const int iv = f.add_view(idx, sizeof(idx));
  const int vv = f.add_view(val, sizeof(val));
  f.json()["accessors"][0]["sparse"] = {{"count", 2},
                                        {"indices", {{"bufferView", iv}, {"componentType", 5123}}},
                                        {"values", {{"bufferView", vv}}}};
  const Scene s = load_gltf(f.write_glb("scene"), quiet());
  expect_near(s.meshes[0].positions[3], {5, 5, 0});
  expect_near(s.meshes[0].positions[0], {-1, -1, 0});
  expect_near(s.meshes[0].positions[1], {1, 0, 0});
}

TEST(GltfLoad, NormalizedByteTexcoords) {
  GltfFixture f("unorm_uv");
  f.add_quad_mesh(true, true);
  const std::uint8_t uv[8] = {0, 255, 255, 255, 0, 0, 255, 51};
  const int view = f.add_view(uv, sizeof(uv));
  f.json()["accessors"].push_back({{"bufferView", view},
                                   {"componentType", 5121},
                                   {"normalized", true},
                                   {"count", 4},
                                   {"type", "VEC2"}});
  f.json()["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] =
      f.json()["accessors"].size() - 1;
  const Scene s = load_gltf(f.write_glb("scene"), quiet());
  EXPECT_FLOAT_EQ(s.meshes[0].uvs[0].y, 1.0f);
  EXPECT_FLOAT_EQ(s.meshes[0].uvs[3].y, 0.2f);
}

TEST(GltfLoad, CameraFromFirstCameraNode) {
  GltfFixture f("camera");
  f.add_quad_mesh(true, true);
  f.json()["cameras"] = {
      {{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.05}}}}};
  // Camera at (0, 0, 4) looking down its -Z, i.e. at the quad.
  f.json()["nodes"].push_back({{"camera", 0}, {"translation", {0.5, 0.5, 4}}});
  f.json()["scenes"][0]["nodes"].push_back(1);
  const Scene s = load_gltf(f.write_glb("scene"), quiet());
  expect_near(s.camera.position, {0.5f, 0.5f, 4.0f});
  expect_near(s.camera.target, {0.5f, 0.5f, 0.0f});
  expect_near(s.camera.up, {0, 1, 0});
  EXPECT_FLOAT_EQ(s.camera.yfov_radians, 0.7f);
  EXPECT_FLOAT_EQ(s.camera.znear, 0.05f);
  EXPECT_GT(s.camera.zfar, 4.0f);  // infinite in the file: a far plane past the scene
}

TEST(GltfLoad, OrthographicCameraKeepsYmag) {
  GltfFixture f("ortho_camera");
  f.add_quad_mesh(true, true);
  f.json()["cameras"] = {
      {{"type", "orthographic"},
       {"orthographic", {{"xmag", 3.0}, {"ymag", 0.75}, {"znear", 0.0}, {"zfar", 9.0}}}}};
  f.json()["nodes"].push_back({{"camera", 0}, {"translation", {0.5, 0.5, 4}}});
  f.json()["scenes"][0]["nodes"].push_back(1);
  std::vector<std::string> warnings;
  const Scene s = load_gltf(f.write_glb("scene"), quiet(&warnings));
  EXPECT_EQ(s.camera.projection, Projection::kOrthographic);
  EXPECT_FLOAT_EQ(s.camera.ymag, 0.75f);
  EXPECT_FLOAT_EQ(s.camera.znear, 0.0f);
  EXPECT_FLOAT_EQ(s.camera.zfar, 9.0f);
  expect_near(s.camera.position, {0.5f, 0.5f, 4.0f});
  expect_near(s.camera.target, {0.5f, 0.5f, 0.0f});
  for (const std::string& w : warnings) EXPECT_EQ(w.find("orthographic"), std::string::npos) << w;
}

TEST(GltfLoad, AutoCameraFramesFromFront) {
  GltfFixture f("auto_camera");
  f.add_quad_mesh(true, true);
  LoadOptions o = quiet();
  const Scene s = load_gltf(f.write_glb("scene"), o);
  expect_near(s.camera.target, {0.5f, 0.5f, 0.0f});
  EXPECT_GT(s.camera.position.z, 0.5f);
  EXPECT_FLOAT_EQ(s.camera.position.x, 0.5f);
  // The unit quad fits vertically: half-height 0.5 within tan(fov/2) * distance.
  const float dist = s.camera.position.z;
  EXPECT_GE(std::tan(0.5f * s.camera.yfov_radians) * dist, 0.5f);
  EXPECT_LT(s.camera.znear, dist);
  EXPECT_GT(s.camera.zfar, dist);
}

TEST(GltfLoad, DirectionalLightFromExtension) {
  GltfFixture f("light");
  f.add_quad_mesh(true, true);
  f.json()["extensionsUsed"] = {"KHR_lights_punctual"};
  f.json()["extensionsRequired"] = {"KHR_lights_punctual"};
  f.json()["extensions"] = {
      {"KHR_lights_punctual",
       {{"lights", {{{"type", "directional"}, {"color", {1, 0.5, 0.25}}, {"intensity", 2}}}}}}};
  // Rotated -90 degrees about X: the light's -Z points down (-Y), so towards it is +Y.
  const float h = std::sqrt(0.5f);
  f.json()["nodes"].push_back(
      {{"rotation", {-h, 0, 0, h}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  f.json()["scenes"][0]["nodes"].push_back(1);
  const Scene s = load_gltf(f.write_glb("scene"), quiet());
  expect_near(s.key_light.direction, {0, 1, 0});
  expect_near(s.key_light.radiance, {2, 1, 0.5f});
}

TEST(GltfLoad, DefaultLightAndEnvironmentWithoutExtension) {
  GltfFixture f("default_light");
  f.add_quad_mesh(true, true);
  const Scene s = load_gltf(f.write_glb("scene"), quiet());
  EXPECT_LT(s.key_light.direction.x, 0.0f);  // from the left
  EXPECT_GT(s.key_light.direction.y, 0.0f);  // from above
  EXPECT_GT(s.key_light.direction.z, 0.0f);  // from the front
  EXPECT_EQ(s.environment.size, 4);
  for (const auto& face : s.environment.faces) EXPECT_EQ(face.size(), 16u);
}

// A 2x1 RGBA PNG: (255, 0, 0, 255), (0, 128, 255, 64).

TEST(GltfLoad, MaterialsAndEmbeddedImages) {
  GltfFixture f("materials");
  f.add_quad_mesh(true, true);
  f.add_png_texture();
  f.json()["materials"] = {{{"name", "Face"},
                            {"pbrMetallicRoughness",
                             {{"baseColorFactor", {0.5, 0.25, 1, 1}},
                              {"baseColorTexture", {{"index", 0}}},
                              {"metallicFactor", 0.0},
                              {"roughnessFactor", 0.4},
                              {"metallicRoughnessTexture", {{"index", 0}}}}},
                            {"normalTexture", {{"index", 0}, {"scale", 0.5}}},
                            {"extras", {{"skinsim", {{"kind", "skin"}}}}}}};
  f.json()["meshes"][0]["primitives"][0]["material"] = 0;
  const Scene s = load_gltf(f.write_glb("scene"), quiet());
  ASSERT_EQ(s.materials.size(), 1u);
  const Material& m = s.materials[0];
  EXPECT_EQ(m.name, "Face");
  EXPECT_EQ(m.kind, MaterialKind::kSkin);
  EXPECT_EQ(m.extras_kind, "skin");
  EXPECT_FLOAT_EQ(m.base_color_factor.y, 0.25f);
  EXPECT_FLOAT_EQ(m.metallic_factor, 0.0f);
  EXPECT_FLOAT_EQ(m.roughness_factor, 0.4f);
  EXPECT_FLOAT_EQ(m.normal_scale, 0.5f);
  // Same image as colour (sRGB) and as data (linear): two scene images, decoded once each.
  ASSERT_EQ(s.images.size(), 2u);
  const Image& color = s.images[m.base_color_texture];
  EXPECT_TRUE(color.srgb);
  EXPECT_FALSE(s.images[m.normal_texture].srgb);
  EXPECT_EQ(m.normal_texture, m.metallic_roughness_texture);
  ASSERT_EQ(color.width, 2);
  ASSERT_EQ(color.height, 1);
  EXPECT_FLOAT_EQ(color.texels[0].r, 1.0f);
  EXPECT_FLOAT_EQ(color.texels[0].g, 0.0f);
  EXPECT_FLOAT_EQ(color.texels[1].g, 128.0f / 255.0f);
  EXPECT_FLOAT_EQ(color.texels[1].a, 64.0f / 255.0f);
}

// KHR_materials_specular's factor is the reflectivity; the textures skinsim does not read
// (occlusion: it bakes its own; the specular extension's textures) are named, not dropped
// silently.
TEST(GltfLoad, SpecularFactorReadAndUnreadTexturesNamed) {
  GltfFixture f("unread_textures");
  f.add_quad_mesh(true, true);
  f.add_png_texture();
  f.json()["materials"] = {{{"name", "skin"},
                            {"occlusionTexture", {{"index", 0}}},
                            {"extensions",
                             {{"KHR_materials_specular",
                               {{"specularFactor", 0.5}, {"specularTexture", {{"index", 0}}}}}}}}};
  f.json()["meshes"][0]["primitives"][0]["material"] = 0;
  std::vector<std::string> warnings;
  const Scene s = load_gltf(f.write_glb("scene"), quiet(&warnings));
  EXPECT_FLOAT_EQ(s.materials[0].reflectivity, 0.5f);
  int named = 0;
  for (const std::string& w : warnings) {
    named += w.find("materials[0].occlusionTexture ignored") != std::string::npos;
    named += w.find("KHR_materials_specular.specularTexture ignored") != std::string::npos;
  }
  EXPECT_EQ(named, 2);
}

TEST(GltfLoad, SkinOverrideBeatsExtras) {
  GltfFixture f("override");
  f.add_quad_mesh(true, true);
  f.json()["materials"] = {{{"name", "Body"}, {"extras", {{"skinsim", {{"kind", "other"}}}}}}};
  f.json()["meshes"][0]["primitives"][0]["material"] = 0;
  const std::string path = f.write_glb("scene");
  EXPECT_EQ(load_gltf(path, quiet()).materials[0].kind, MaterialKind::kOther);
  LoadOptions o = quiet();
  o.skin_materials = {"Body"};
  EXPECT_EQ(load_gltf(path, o).materials[0].kind, MaterialKind::kSkin);
}

TEST(GltfLoad, UnitsOverride) {
  GltfFixture f("units");
  f.add_quad_mesh(true, true);
  LoadOptions o = quiet();
  o.units_per_mm = 0.04f;
  EXPECT_FLOAT_EQ(load_gltf(f.write_glb("scene"), o).units_per_mm, 0.04f);
}

TEST(GltfLoad, LeePerrySmith) {
  const std::string path = test_paths::kLeePerrySmith;
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "asset not found: " << path;
  LoadOptions o = quiet();
  o.environment_size = 64;  // as in real use
  o.skin_materials = {"all"};
  const Scene s = load_gltf(path, o);
  std::size_t triangles = 0;
  for (const Mesh& m : s.meshes) {
    triangles += m.triangle_count();
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      ASSERT_NEAR(glm::length(m.normals[i]), 1.0f, 1e-4f) << "vertex " << i;
      const glm::vec3 t(m.tangents[i]);
      ASSERT_NEAR(glm::length(t), 1.0f, 1e-4f) << "vertex " << i;
      ASSERT_NEAR(glm::dot(t, m.normals[i]), 0.0f, 1e-4f) << "vertex " << i;
      ASSERT_TRUE(m.tangents[i].w == 1.0f || m.tangents[i].w == -1.0f);
    }
  }
  EXPECT_EQ(triangles, 17684u);
  EXPECT_EQ(s.materials[0].kind, MaterialKind::kSkin);
  // The file's camera/lamp nodes are in another scene; ours frames the face from the front
  // (+Z; test_scene_head checks the head it measures).
  const Bounds b = scene_bounds(s);
  EXPECT_GT(s.camera.position.z, b.max.z);
  ASSERT_TRUE(s.head);
  expect_near(s.camera.target, s.head->centre(), 1e-4f);
}

}  // namespace
}  // namespace skinsim::scene
