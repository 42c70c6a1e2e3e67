// The user's reference store on hand-made images: what it returns, what it refuses, which
// references it evicts, and where the environment puts it. No rendering, fast.
#include "driver/frame/reference_store.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "image/image.h"
#include "tests/scoped_env.h"
#include "tests/test_paths.h"
#include "util/user_error.h"

namespace skinsim::driver {
namespace {

namespace fs = std::filesystem;
using test::ScopedEnv;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(test_paths::kTestsBinaryDir) / "driver" / "reference_store" / name;
  fs::remove_all(dir);
  return dir;
}

// A 4x3 reference whose pixels are 8-bit values (as a loaded reference's are) that depend on
// `seed`, and a skin mask over its left half.
ReferenceImages images(int seed) {
  ReferenceImages r;
  r.image = image::Image::filled(4, 3, glm::vec3(0.0f));
  r.skin = image::Mask::filled(4, 3, 0);
  for (int i = 0; i < 12; ++i) {
    const int k = (seed * 37 + i * 11) % 256;
    r.image.rgb[i] = glm::vec3(k, 255 - k, (k * 7) % 256) / 255.0f;
    r.skin.values[i] = i % 4 < 2 ? 1 : 0;
  }
  return r;
}

nlohmann::json marker(int seed) {
  return {{"fingerprint", {{"knobs", {{"light_azimuth", seed}}}}}, {"build", "test"}};
}

std::size_t files_in(const fs::path& dir) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), {}));
}

TEST(ReferenceStore, GivesBackWhatItKeptUnderTheSameMarkerOnly) {
  const ReferenceStore store(fresh_dir("round_trip"));
  EXPECT_FALSE(store.load(marker(1), 4, 3).images);  // the directory does not exist yet
  ASSERT_EQ(store.keep(marker(1), images(1)), "");
  const std::optional<ReferenceImages> back = store.load(marker(1), 4, 3).images;
  ASSERT_TRUE(back);
  EXPECT_EQ(back->image.rgb, images(1).image.rgb);  // exactly: 8-bit values survive the PNG
  EXPECT_EQ(back->skin.values, images(1).skin.values);
  EXPECT_FALSE(store.load(marker(2), 4, 3).images);
  nlohmann::json other_build = marker(1);
  other_build["build"] = "another";
  EXPECT_FALSE(store.load(other_build, 4, 3).images);
}

TEST(ReferenceStore, ADamagedCopyIsNoCopy) {
  const fs::path dir = fresh_dir("damaged");
  const ReferenceStore store(dir);
  ASSERT_EQ(store.keep(marker(1), images(1)), "");
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    if (e.path().string().ends_with("_skin.png")) {
      std::ofstream(e.path(), std::ios::binary | std::ios::trunc) << "not a png";
    }
  }
  EXPECT_FALSE(store.load(marker(1), 4, 3).images);
  ASSERT_EQ(store.keep(marker(1), images(1)), "");  // kept again over the damaged copy
  EXPECT_TRUE(store.load(marker(1), 4, 3).images);
}

TEST(ReferenceStore, EvictsTheLeastRecentlyUsedBeyondItsCapacity) {
  const fs::path dir = fresh_dir("evict");
  const ReferenceStore store(dir, 2);
  // Markers' times tell the order of use; file systems keep them to a few ms at worst.
  const auto tick = [] { std::this_thread::sleep_for(std::chrono::milliseconds(20)); };
  ASSERT_EQ(store.keep(marker(1), images(1)), "");
  tick();
  ASSERT_EQ(store.keep(marker(2), images(2)), "");
  tick();
  ASSERT_TRUE(store.load(marker(1), 4, 3).images);  // used: now the most recent
  tick();
  ASSERT_EQ(store.keep(marker(3), images(3)), "");
  EXPECT_TRUE(store.load(marker(1), 4, 3).images);
  EXPECT_FALSE(
      store.load(marker(2), 4, 3).images);  // the least recently used: gone, all three files
  EXPECT_TRUE(store.load(marker(3), 4, 3).images);
  EXPECT_EQ(files_in(dir), 6u);
}

TEST(ReferenceStore, AReadOnlyStoreIsNoErrorButSaysWhy) {
  const fs::path dir = fresh_dir("blocked");
  fs::create_directories(dir.parent_path());
  std::ofstream(dir) << "a file where the store's directory would be";
  const ReferenceStore store(dir);
  EXPECT_NE(store.keep(marker(1), images(1)), "");
  EXPECT_FALSE(store.load(marker(1), 4, 3).images);
}

TEST(ReferenceStore, TheEnvironmentChoosesTheDirectory) {
  const ScopedEnv xdg("XDG_CACHE_HOME", "/xdg/cache");
  const ScopedEnv home("HOME", "/home/someone");
  {
    for (const char* off : {"off", "OFF", "Off"}) {
      const ScopedEnv cache("SKINSIM_CACHE_DIR", off);
      EXPECT_FALSE(ReferenceStore::from_environment()) << off;
    }
  }
  {
    const ScopedEnv cache("SKINSIM_CACHE_DIR", "/some/cache");
    EXPECT_EQ(ReferenceStore::from_environment()->dir(), fs::path("/some/cache/references"));
  }
  const ScopedEnv unset("SKINSIM_CACHE_DIR", std::nullopt);
  EXPECT_EQ(ReferenceStore::from_environment()->dir(), fs::path("/xdg/cache/skinsim/references"));
  {
    const ScopedEnv relative("XDG_CACHE_HOME", "relative/cache");  // the XDG spec ignores it
    EXPECT_EQ(ReferenceStore::from_environment()->dir(),
              fs::path("/home/someone/.cache/skinsim/references"));
    const ScopedEnv no_home("HOME", std::nullopt);
    EXPECT_FALSE(ReferenceStore::from_environment());
  }
}

// A store may be shared (a cluster's scratch directory) or edited by hand: a copy is used only
// when its marker parses, describes the reference asked for, and its images are regular files
// whose size and pixels are the marker's. Everything else is discarded with a reason.
struct Tampering {
  const char* name;
  std::function<void(const fs::path& dir, const std::string& stem)> apply;
  const char* reason;  // part of KeptReference::discarded
};

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

std::vector<Tampering> tamperings() {
  return {
      {"empty_marker", [](auto& d, auto& s) { write(d / (s + ".json"), ""); }, "not valid JSON"},
      {"garbage_marker", [](auto& d, auto& s) { write(d / (s + ".json"), "{garbage"); },
       "not valid JSON"},
      {"text_marker", [](auto& d, auto& s) { write(d / (s + ".json"), "kept\n"); },
       "not valid JSON"},
      {"deep_marker", [](auto& d, auto& s) { write(d / (s + ".json"), std::string(20000, '[')); },
       "nests deeper than 64"},
      {"array_marker", [](auto& d, auto& s) { write(d / (s + ".json"), "[1]"); },
       "not a JSON object"},
      {"marker_without_digest",
       [](auto& d, auto& s) { write(d / (s + ".json"), marker(1).dump()); },
       "does not describe 4x3"},
      {"swapped_images",  // the same size, another reference's pixels
       [](auto& d, auto& s) {
         const ReferenceStore other(d / "other");
         ASSERT_EQ(other.keep(marker(1), images(2)), "");
         fs::copy_file(d / "other" / (s + ".png"), d / (s + ".png"),
                       fs::copy_options::overwrite_existing);
       },
       "not the ones its marker describes"},
      {"smaller_images",  // a 2x2 reference's files in place of the 4x3 one's
       [](auto& d, auto& s) {
         ReferenceImages small = images(1);
         small.image = image::Image::filled(2, 2, glm::vec3(0.5f));
         small.skin = image::Mask::filled(2, 2, 1);
         image::save_png(small.image, d / (s + ".png"));
         image::save_mask_png(small.skin, d / (s + "_skin.png"));
       },
       "not the ones its marker describes"},
      {"image_symlink",  // a link to a good copy elsewhere is not the store's own file
       [](auto& d, auto& s) {
         fs::rename(d / (s + ".png"), d / "elsewhere.png");
         fs::create_symlink(d / "elsewhere.png", d / (s + ".png"));
       },
       "not regular files"},
      {"marker_symlink",
       [](auto& d, auto& s) {
         fs::rename(d / (s + ".json"), d / "elsewhere.json");
         fs::create_symlink(d / "elsewhere.json", d / (s + ".json"));
       },
       "is a symlink"},
      {"mask_missing", [](auto& d, auto& s) { fs::remove(d / (s + "_skin.png")); }, "missing"},
  };
}

void PrintTo(const Tampering& tampering, std::ostream* os) {
  *os << tampering.name;
}

class TamperedStore : public ::testing::TestWithParam<Tampering> {};

TEST_P(TamperedStore, IsDiscardedWithAReasonAndKeptAgain) {
  const fs::path dir = fresh_dir(std::string("tampered_") + GetParam().name);
  const ReferenceStore store(dir);
  ASSERT_EQ(store.keep(marker(1), images(1)), "");
  std::string stem;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    if (e.path().extension() == ".json") stem = e.path().stem().string();
  }
  GetParam().apply(dir, stem);
  const KeptReference kept = store.load(marker(1), 4, 3);
  EXPECT_FALSE(kept.images);
  EXPECT_NE(kept.discarded.find(GetParam().reason), std::string::npos) << kept.discarded;
  ASSERT_EQ(store.keep(marker(1), images(1)), "");  // replaces whatever was there
  const KeptReference again = store.load(marker(1), 4, 3);
  ASSERT_TRUE(again.images) << again.discarded;
  EXPECT_EQ(again.images->image.rgb, images(1).image.rgb);
}

INSTANTIATE_TEST_SUITE_P(Cases, TamperedStore, ::testing::ValuesIn(tamperings()),
                         [](const auto& test_info) { return std::string(test_info.param.name); });

TEST(ReferenceStore, AReferenceOfAnotherSizeIsDiscarded) {
  const ReferenceStore store(fresh_dir("other_size"));
  ASSERT_EQ(store.keep(marker(1), images(1)), "");
  const KeptReference kept = store.load(marker(1), 8, 6);  // the frame is 8x6
  EXPECT_FALSE(kept.images);
  EXPECT_NE(kept.discarded.find("does not describe 8x6"), std::string::npos) << kept.discarded;
}

TEST(ReferenceStore, NeverWritesThroughAPlantedSymlink) {
  const fs::path dir = fresh_dir("planted");
  const ReferenceStore store(dir);
  ASSERT_EQ(store.keep(marker(1), images(1)), "");
  const fs::path outside = fresh_dir("planted_outside");
  fs::create_directories(outside);
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    const fs::path victim = outside / e.path().filename();
    write(victim, "not skinsim's");
    fs::remove(e.path());
    fs::create_symlink(victim, e.path());
  }
  ASSERT_EQ(store.keep(marker(1), images(1)), "");
  for (const fs::directory_entry& e : fs::directory_iterator(outside)) {
    std::ifstream in(e.path());
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "not skinsim's") << e.path();
  }
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    EXPECT_FALSE(e.is_symlink()) << e.path();
  }
  EXPECT_TRUE(store.load(marker(1), 4, 3).images);
}

TEST(ReferenceStore, UnusableCacheDirectoryValuesAreErrors) {
  const fs::path dangling = fresh_dir("dangling");
  fs::create_directories(dangling.parent_path());
  fs::create_symlink(dangling.string() + "_nowhere", dangling);
  for (const std::string& value :
       {dangling.string(), std::string("/tmp/a\nb"), std::string("/tmp/\x1b[31mred")}) {
    const ScopedEnv cache("SKINSIM_CACHE_DIR", value);
    try {
      ReferenceStore::from_environment();
      FAIL() << "no error for " << value;
    } catch (const UserError& e) {
      EXPECT_NE(std::string(e.what()).find("SKINSIM_CACHE_DIR"), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\x1b'), std::string::npos) << e.what();
    }
  }
}

TEST(ReferenceStore, ACacheDirectoryThatIsAFileIsAnError) {
  const fs::path file = fresh_dir("not_a_directory");
  fs::create_directories(file.parent_path());
  std::ofstream(file) << "x";
  const ScopedEnv cache("SKINSIM_CACHE_DIR", file.string());
  try {
    ReferenceStore::from_environment();
    FAIL() << "no error";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("SKINSIM_CACHE_DIR"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace skinsim::driver
