// Sizing a scan from its head (head_measure.h, scene_scale.h), framing the face
// (camera_framing.h) and --skin-albedo (skin_albedo.h): on the built-in head, whose shape is
// known analytically, on copies of it in other units and orientations, and on the real
// LeePerrySmith bust.
#include "scene/head_measure.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/bounds.h"
#include "scene/camera_framing.h"
#include "scene/error.h"
#include "scene/gltf_loader.h"
#include "scene/head_shape.h"
#include "scene/procedural_head.h"
#include "scene/scene_scale.h"
#include "scene/skin_albedo.h"
#include "scene/sole_skin.h"
#include "tests/scene/gltf_fixture.h"
#include "tests/test_paths.h"

namespace skinsim::scene {
namespace {

const Scene& builtin_head() {
  static const Scene s = [] {
    DefaultSceneOptions o;
    o.head_triangles = 60000;  // the default: what a run measures
    o.texture_size = 16;
    o.eye_texture_size = 16;
    o.environment_size = 4;
    return make_default_scene(o);
  }();
  return s;
}

// The built-in head's crown-to-chin height from its analytic midline profile (u = 0.5, the
// front centre line), with the chin defined as in head_measure.h: below the nose tip, the
// profile point furthest along the direction halfway between forward and down.
struct Profile {
  float crown_y, nose_y, chin_y;
};
Profile analytic_profile() {
  constexpr int kSteps = 20000;
  Profile p{head::surface_point(0.5f, 0.0f).y, 0.0f, 0.0f};
  float nose_z = -1.0f, best = -1.0f;
  int nose = 0;
  for (int i = 0; i <= kSteps; ++i) {  // the nose: the most forward point
    const glm::vec3 q = head::surface_point(0.5f, static_cast<float>(i) / kSteps);
    if (q.z > nose_z) nose_z = q.z, p.nose_y = q.y, nose = i;
  }
  // From 0.3 crown-to-nose lengths below the nose to where the profile falls back 0.1 of it.
  const float length = p.crown_y - p.nose_y;
  float best_z = 0.0f;
  for (int i = nose; i <= kSteps; ++i) {
    const glm::vec3 q = head::surface_point(0.5f, static_cast<float>(i) / kSteps);
    if (p.nose_y - q.y < 0.3f * length) continue;
    if (best > 0.0f && q.z < best_z - 0.1f * length) break;
    if (q.z - q.y > best) {
      best = q.z - q.y;
      best_z = q.z;
      p.chin_y = q.y;
    }
  }
  return p;
}

// A copy of `s` with every position mapped by `f` (a change of units or orientation).
template <class F>
Scene transformed(const Scene& s, F f) {
  Scene out = s;
  for (Mesh& m : out.meshes) {
    for (glm::vec3& p : m.positions) p = f(p);
  }
  return out;
}

std::vector<std::string>* sink(std::vector<std::string>& warnings) {
  warnings.clear();
  return &warnings;
}
auto collect(std::vector<std::string>* to) {
  return [to](const std::string& w) { to->push_back(w); };
}

TEST(HeadMeasure, BuiltInHeadMatchesItsAnalyticShape) {
  const HeadMeasure m = measure_head(builtin_head());
  ASSERT_TRUE(m.head) << m.why_not;
  const Profile truth = analytic_profile();
  // The shape's own comment says 0.24 m from crown to chin (its ellipsoid); the chin's 45
  // degree point sits above the bottom of the chin: 0.222 m.
  EXPECT_NEAR(truth.crown_y - truth.chin_y, 0.23f, 0.015f);
  // The mesh is cut every 1/400 of its 0.38 m height (< 1 mm) and is a tessellation: 2 mm.
  EXPECT_NEAR(m.head->crown.y, truth.crown_y, 0.002f);
  EXPECT_NEAR(m.head->nose_tip.y, truth.nose_y, 0.002f);
  EXPECT_NEAR(m.head->chin.y, truth.chin_y, 0.002f);
  EXPECT_NEAR(m.head->nose_tip.x, 0.0f, 0.002f);
  // The box is the head from chin to crown: narrower than the neck-and-head skin is tall.
  EXPECT_FLOAT_EQ(m.head->box_max.y, m.head->crown.y);
  EXPECT_FLOAT_EQ(m.head->box_min.y, m.head->chin.y);
  EXPECT_NEAR(m.head->box_max.x - m.head->box_min.x, 0.16f, 0.03f);  // about 0.16 m wide
}

TEST(SceneScale, MetresKeptWhenPlausibleAndAHeadInOtherUnitsIsSizedFromItself) {
  std::vector<std::string> warnings;
  Scene metres = builtin_head();
  size_scene(metres, 0.0f, collect(sink(warnings)));
  EXPECT_EQ(metres.units_source, UnitsSource::kFile);
  EXPECT_FLOAT_EQ(metres.units_per_mm, 0.001f);
  EXPECT_TRUE(warnings.empty());
  const float height_m = metres.head->height();

  // The same head in centimetres, the neck still attached: sized from the head, not the
  // box (which is 0.38 m, 1.6 x the head).
  Scene cm = transformed(builtin_head(), [](const glm::vec3& p) { return p * 100.0f; });
  size_scene(cm, 0.0f, collect(sink(warnings)));
  EXPECT_EQ(cm.units_source, UnitsSource::kHeadHeight);
  EXPECT_NEAR(cm.units_per_mm, 100.0f * height_m / kTypicalHeadMm, 1e-4f);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("sized as a life-size head"), std::string::npos) << warnings[0];
  EXPECT_NE(describe_scale(cm).find("crown to chin"), std::string::npos);

  // --units-per-mm wins; a wrong one is named with the head-based suggestion.
  Scene given = cm;
  size_scene(given, 0.001f, collect(sink(warnings)));
  EXPECT_EQ(given.units_source, UnitsSource::kGiven);
  EXPECT_FLOAT_EQ(given.units_per_mm, 0.001f);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("crown to chin"), std::string::npos) << warnings[0];
  char suggestion[64];
  std::snprintf(suggestion, sizeof suggestion, "--units-per-mm %.3g",
                100.0f * height_m / kTypicalHeadMm);
  EXPECT_NE(warnings[0].find(suggestion), std::string::npos) << warnings[0];
}

TEST(SceneScale, NoHeadWhenTheFaceLooksBackSaysWhyAndFallsBackToTheBox) {
  std::vector<std::string> warnings;
  // Turned to face -Z (and in centimetres): the front profile is the back of the head.
  Scene back = transformed(builtin_head(),
                           [](const glm::vec3& p) { return glm::vec3(-p.x, p.y, -p.z) * 100.0f; });
  const HeadMeasure m = measure_head(back);
  EXPECT_FALSE(m.head);
  EXPECT_FALSE(m.why_not.empty());
  size_scene(back, 0.0f, collect(sink(warnings)));
  EXPECT_EQ(back.units_source, UnitsSource::kBoxHeight);
  Bounds skin;  // the scene also holds the eyes and a backdrop
  for (const Mesh& mesh : back.meshes) {
    if (back.materials[static_cast<std::size_t>(mesh.material)].kind == MaterialKind::kSkin)
      skin.grow(mesh_bounds(mesh));
  }
  EXPECT_NEAR(back.units_per_mm, skin.extent().y / kTypicalHeadMm, 1e-4f);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("no head found"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find(m.why_not), std::string::npos) << warnings[0];
}

TEST(FrameFace, AimsAtTheHeadAndFitsIt) {
  const HeadLandmarks head = *measure_head(builtin_head()).head;
  const Camera cam = frame_face(head, 0.5f, 4.0f / 3.0f);
  EXPECT_NEAR(cam.target.y, 0.5f * (head.crown.y + head.chin.y), 1e-5f);
  EXPECT_GT(cam.position.z, head.nose_tip.z);
  // Crown to chin with 10% to spare fills the frame's height.
  const float half_view = std::tan(0.25f) * (cam.position.z - head.box_max.z);
  EXPECT_NEAR(half_view, 0.55f * head.height(), 0.05f * head.height());
}

TEST(HeadMeasure, LeePerrySmithBustIsSizedFromItsHead) {
  const std::string path = test_paths::kLeePerrySmith;
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "asset not found: " << path;
  std::vector<std::string> warnings;
  LoadOptions o;
  o.skin_materials = {"all"};
  o.environment_size = 4;
  o.warn = collect(&warnings);
  const Scene s = load_gltf(path, o);
  ASSERT_TRUE(s.head);
  // Measured by hand from the mesh's side profile (front-most point of 0.05-unit slices):
  // crown y 3.97, nose tip z 2.59 at y 1.1-1.2, the chin's front (z 2.2-2.3) turning into
  // its underside between y -0.35 and -0.6 (under it z falls to 1.3 by y -0.8).
  EXPECT_NEAR(s.head->crown.y, 3.97f, 0.01f);
  EXPECT_NEAR(s.head->nose_tip.z, 2.59f, 0.02f);
  EXPECT_NEAR(s.head->nose_tip.y, 1.15f, 0.1f);
  EXPECT_GE(s.head->chin.y, -0.6f);
  EXPECT_LE(s.head->chin.y, -0.35f);
  // So 4.3-4.6 units crown to chin (not the box's 7.95), 0.019-0.021 units per mm.
  EXPECT_EQ(s.units_source, UnitsSource::kHeadHeight);
  EXPECT_GE(s.units_per_mm, 4.32f / kTypicalHeadMm);
  EXPECT_LE(s.units_per_mm, 4.57f / kTypicalHeadMm);
  // The camera aims at the face, well above the bust's centre (y 0).
  EXPECT_NEAR(s.camera.target.y, 0.5f * (s.head->crown.y + s.head->chin.y), 1e-4f);
  EXPECT_GT(s.camera.target.y, scene_bounds(s).center().y + 1.0f);
  bool sized = false;
  for (const std::string& w : warnings) sized = sized || w.find("life-size head") != w.npos;
  EXPECT_TRUE(sized);
}

// --skin-albedo on a one-quad scan whose material is skin.
class SkinAlbedo : public ::testing::Test {
 protected:
  Scene load(const std::string& albedo) {
    f_.add_quad_mesh(true, true);
    f_.json()["materials"] = {
        {{"name", "skin"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.6, 0.6, 0.8, 1}}}}}};
    f_.json()["meshes"][0]["primitives"][0]["material"] = 0;
    LoadOptions o;
    o.environment_size = 4;
    o.skin_albedo = albedo;
    o.warn = collect(&warnings_);
    return load_gltf(f_.write_glb("scan"), o);
  }
  testing::GltfFixture f_{"skin_albedo"};
  std::vector<std::string> warnings_;
};

TEST_F(SkinAlbedo, ColourIsDecodedFromSrgb) {
  const Scene s = load("194, 150,130");
  const Material& m = s.materials[0];
  EXPECT_EQ(m.base_color_texture, -1);
  // IEC 61966-2-1: 194/255 -> 0.5395, 150/255 -> 0.3049, 130/255 -> 0.2232.
  EXPECT_NEAR(m.base_color_factor.r, 0.5395f, 1e-4f);
  EXPECT_NEAR(m.base_color_factor.g, 0.3049f, 1e-4f);
  EXPECT_NEAR(m.base_color_factor.b, 0.2232f, 1e-4f);
  EXPECT_FLOAT_EQ(m.base_color_factor.a, 1.0f);
  for (const std::string& w : warnings_) EXPECT_EQ(w.find("no textures"), w.npos) << w;
}

TEST_F(SkinAlbedo, ImageBecomesAnSrgbBaseColourTexture) {
  const std::string path = f_.write_raw(
      "albedo.png", std::string(testing::kTwoPixelPng.begin(), testing::kTwoPixelPng.end()));
  const Scene s = load(path);
  const Material& m = s.materials[0];
  ASSERT_GE(m.base_color_texture, 0);
  const Image& image = s.images[static_cast<std::size_t>(m.base_color_texture)];
  EXPECT_TRUE(image.srgb);  // decoded by the sampler, as a glTF baseColorTexture
  ASSERT_EQ(image.width, 2);
  EXPECT_EQ(image.texels[0], glm::vec4(1, 0, 0, 1));
  EXPECT_NEAR(image.texels[1].g, 128.0f / 255.0f, 1e-6f);
  EXPECT_EQ(glm::vec3(m.base_color_factor), glm::vec3(1.0f));
}

TEST_F(SkinAlbedo, BadInputNamesTheOption) {
  for (const std::string bad : {"300,0,0", "1,2", "/nonexistent/albedo.png"}) {
    try {
      load(bad);
      ADD_FAILURE() << bad << " accepted";
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find("--skin-albedo"), std::string::npos) << e.what();
    }
  }
}

// The built-in head's skin alone, as a scan without names would have it: one material.
Scene unnamed_head_scan(const std::vector<std::string>& material_names) {
  Scene s;
  const Scene& builtin = builtin_head();
  for (const std::string& name : material_names) {
    Material m;
    m.name = name;
    s.materials.push_back(m);
  }
  for (const Mesh& m : builtin.meshes) {
    if (builtin.materials[m.material].kind != MaterialKind::kSkin) continue;
    Mesh copy = m;
    copy.material = 0;
    s.meshes.push_back(std::move(copy));
  }
  classify_materials(s, {});
  return s;
}

TEST(SoleSkin, AScansOnlyMaterialShapedLikeAHeadIsSkin) {
  Scene s = unnamed_head_scan({"Material.002"});
  ASSERT_EQ(s.materials[0].kind, MaterialKind::kOther);  // by name
  const std::string note = take_sole_material_as_skin(s);
  EXPECT_EQ(s.materials[0].kind, MaterialKind::kSkin);
  EXPECT_NE(note.find("'Material.002' is taken as skin"), std::string::npos) << note;
}

TEST(SoleSkin, NotWhenTwoMaterialsCouldBeSkinOrOneIsMarkedOther) {
  Scene two = unnamed_head_scan({"Material.002", "Material.003"});
  EXPECT_EQ(take_sole_material_as_skin(two), "");
  EXPECT_EQ(two.materials[0].kind, MaterialKind::kOther);
  Scene marked = unnamed_head_scan({"Material.002"});
  marked.materials[0].extras_kind = "other";
  EXPECT_EQ(take_sole_material_as_skin(marked), "");
  EXPECT_EQ(marked.materials[0].kind, MaterialKind::kOther);
}

TEST(SoleSkin, NotWhenItsShapeIsNoHead) {
  Scene card;
  card.materials.push_back(Material{});
  card.materials[0].name = "card";
  Mesh quad;
  quad.material = 0;
  quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  quad.normals.assign(4, glm::vec3(0, 0, 1));
  quad.indices = {0, 1, 2, 0, 2, 3};
  card.meshes.push_back(quad);
  EXPECT_EQ(take_sole_material_as_skin(card), "");
  EXPECT_EQ(card.materials[0].kind, MaterialKind::kOther);
}

TEST(SoleSkin, LeePerrySmithIsSkinWithoutSkinMaterials) {
  const std::string path = test_paths::kLeePerrySmith;
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "asset not found: " << path;
  std::vector<std::string> warnings;
  LoadOptions o;
  o.environment_size = 4;
  o.warn = collect(&warnings);
  const Scene s = load_gltf(path, o);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].kind, MaterialKind::kSkin);
  ASSERT_TRUE(s.head);
  bool said = false;
  for (const std::string& w : warnings) said = said || w.find("is taken as skin") != w.npos;
  EXPECT_TRUE(said);
}

}  // namespace
}  // namespace skinsim::scene
