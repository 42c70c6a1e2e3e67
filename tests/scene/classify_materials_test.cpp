#include <gtest/gtest.h>

#include "scene/scene.h"

namespace skinsim::scene {
namespace {

Scene with_materials(const std::vector<std::pair<std::string, std::string>>& name_and_extras) {
  Scene s;
  for (const auto& [name, extras] : name_and_extras) {
    Material m;
    m.name = name;
    m.extras_kind = extras;
    s.materials.push_back(m);
  }
  return s;
}

std::vector<MaterialKind> kinds(const Scene& s) {
  std::vector<MaterialKind> k;
  for (const auto& m : s.materials) k.push_back(m.kind);
  return k;
}

using K = MaterialKind;

TEST(ClassifyMaterials, NamesWhenNothingElseSays) {
  Scene s =
      with_materials({{"Head_SKIN_mat", ""}, {"EyeBall", ""}, {"Shirt", ""}, {"Skin&Eye", ""}});
  classify_materials(s, {});
  EXPECT_EQ(kinds(s), (std::vector<K>{K::kSkin, K::kEye, K::kOther, K::kSkin}));
}

TEST(ClassifyMaterials, ExtrasBeatNames) {
  Scene s = with_materials({{"skin_but_hair", "other"}, {"cornea", "eye"}, {"m", "skin"}});
  classify_materials(s, {});
  EXPECT_EQ(kinds(s), (std::vector<K>{K::kOther, K::kEye, K::kSkin}));
}

TEST(ClassifyMaterials, OverrideBeatsExtrasAndNames) {
  Scene s = with_materials({{"body", "other"}, {"eye_l", ""}, {"cloth", ""}});
  classify_materials(s, {"body", "eye_l"});
  EXPECT_EQ(kinds(s), (std::vector<K>{K::kSkin, K::kSkin, K::kOther}));
}

TEST(ClassifyMaterials, AllMakesEverythingSkin) {
  Scene s = with_materials({{"a", "other"}, {"eye", "eye"}});
  classify_materials(s, {"all"});
  EXPECT_EQ(kinds(s), (std::vector<K>{K::kSkin, K::kSkin}));
}

TEST(ClassifyMaterials, ReclassifiesFromScratch) {
  Scene s = with_materials({{"skin", ""}});
  classify_materials(s, {"all"});
  s.materials[0].name = "cloth";
  classify_materials(s, {});
  EXPECT_EQ(s.materials[0].kind, K::kOther);
}

}  // namespace
}  // namespace skinsim::scene
