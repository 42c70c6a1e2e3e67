// The truth store on hand-made images (driver/truth/truth_store.h): what it returns under which
// key, what it refuses, what it evicts, and that the key follows the exported scene's bytes but not
// its source path. No Blender, no rendering.
#include "driver/truth/truth_store.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "tests/test_paths.h"

namespace skinsim::driver {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(test_paths::kTestsBinaryDir) / "truth" / "truth_store" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A 4x3 truth and its second seed, 8-bit values (as display images are) that depend on `seed`.
TruthImages images(int seed) {
  TruthImages t;
  t.image = image::Image::filled(4, 3, glm::vec3(0.0f));
  t.second = t.image;
  for (int i = 0; i < 12; ++i) {
    const int k = (seed * 37 + i * 11) % 256;
    t.image.rgb[i] = glm::vec3(k, 255 - k, (k * 7) % 256) / 255.0f;
    t.second->rgb[i] = glm::vec3((k + 1) % 256, 255 - k, k) / 255.0f;
  }
  return t;
}

nlohmann::json key(int seed) {
  return {{"format", "test"}, {"seed", seed}};
}

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

TEST(TruthStore, GivesBackWhatItKeptUnderTheSameKeyOnly) {
  const TruthStore store(fresh_dir("same"));
  ASSERT_EQ(store.keep(key(1), images(1)), "");
  const KeptTruth kept = store.load(key(1), 4, 3);
  ASSERT_TRUE(kept.images);
  EXPECT_EQ(kept.images->image.rgb, images(1).image.rgb);
  EXPECT_EQ(kept.images->second->rgb, images(1).second->rgb);
  EXPECT_FALSE(store.load(key(2), 4, 3).images);
  EXPECT_EQ(store.load(key(2), 4, 3).discarded, "");  // none kept: no note
  const KeptTruth other_size = store.load(key(1), 8, 6);
  EXPECT_FALSE(other_size.images);
  EXPECT_NE(other_size.discarded.find("8x6"), std::string::npos) << other_size.discarded;
}

TEST(TruthStore, ASwappedSecondSeedIsDiscarded) {
  const TruthStore store(fresh_dir("swapped"));
  ASSERT_EQ(store.keep(key(1), images(1)), "");
  const fs::path marker = store.marker(key(1));
  const std::string stem = (marker.parent_path() / marker.stem()).string();
  fs::copy_file(stem + ".png", stem + "_second.png", fs::copy_options::overwrite_existing);
  const KeptTruth kept = store.load(key(1), 4, 3);
  EXPECT_FALSE(kept.images);
  EXPECT_NE(kept.discarded.find("not the ones its marker describes"), std::string::npos)
      << kept.discarded;
}

TEST(TruthStore, EvictsTheLeastRecentlyUsedBeyondItsCapacity) {
  const fs::path dir = fresh_dir("evict");
  const TruthStore store(dir, 2);
  const auto tick = [] { std::this_thread::sleep_for(std::chrono::milliseconds(20)); };
  ASSERT_EQ(store.keep(key(1), images(1)), "");
  tick();
  ASSERT_EQ(store.keep(key(2), images(2)), "");
  tick();
  ASSERT_TRUE(store.load(key(1), 4, 3).images);  // used: now the most recent
  tick();
  ASSERT_EQ(store.keep(key(3), images(3)), "");
  EXPECT_TRUE(store.load(key(1), 4, 3).images);
  EXPECT_FALSE(store.load(key(2), 4, 3).images);
  EXPECT_TRUE(store.load(key(3), 4, 3).images);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), {}), 6);
}

TEST(TruthKey, FollowsTheExportedBytesButNotTheSourcePath) {
  const fs::path dir = fresh_dir("key");
  fs::create_directories(dir / "textures");
  write(dir / "meshes.bin", "triangles");
  write(dir / "textures" / "image0.png", "texels");
  write(dir / "script.py", "render()");
  const nlohmann::json scene{{"source", "/home/a/head.glb"},
                             {"width", 4},
                             {"height", 3},
                             {"render", {{"samples", 64}}},
                             {"lights", {1, 2}}};
  const auto key_of = [&dir](const nlohmann::json& exported, int seed,
                             const std::string& blender = "Blender 3.4.1") {
    return truth_key(exported, dir, dir / "script.py", seed, blender);
  };
  const nlohmann::json k = key_of(scene, 1);
  EXPECT_EQ(k["samples"], 64);
  EXPECT_EQ(k["second_seed"], 2);
  EXPECT_EQ(k["blender"], "Blender 3.4.1");

  nlohmann::json moved = scene;
  moved["source"] = "/scratch/b/head.glb";  // the same scan elsewhere: the same truth
  EXPECT_EQ(key_of(moved, 1), k);
  nlohmann::json lit = scene;
  lit["lights"] = {1, 3};
  EXPECT_NE(key_of(lit, 1), k);
  EXPECT_NE(key_of(scene, 2), k);
  // Another Blender's Cycles is another judge.
  EXPECT_NE(key_of(scene, 1, "Blender 4.2.0"), k);
  write(dir / "textures" / "image0.png", "other texels");
  EXPECT_NE(key_of(scene, 1), k);
  write(dir / "textures" / "image0.png", "texels");
  write(dir / "script.py", "render(better)");
  EXPECT_NE(key_of(scene, 1), k);
  write(dir / "script.py", "render()");

  // The same view with other samples and seeds: what `--truth-samples`, `--truth-seed` ask for.
  nlohmann::json more = scene;
  more["render"]["samples"] = 1024;
  const nlohmann::json k1024 = key_of(more, 7);
  EXPECT_NE(k1024, k);
  EXPECT_EQ(with_samples(k, 1024, 7), k1024);
}

}  // namespace
}  // namespace skinsim::driver
