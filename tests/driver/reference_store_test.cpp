// The user's reference store on hand-made images: what it returns, what it refuses, which
// references it evicts, and where the environment puts it. No rendering, fast.
#include "driver/reference_store.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

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
  r.image = quality::Image::filled(4, 3, glm::vec3(0.0f));
  r.skin = quality::Mask::filled(4, 3, 0);
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
  EXPECT_FALSE(store.load(marker(1)));  // the directory does not exist yet
  ASSERT_EQ(store.keep(marker(1), images(1)), "");
  const std::optional<ReferenceImages> back = store.load(marker(1));
  ASSERT_TRUE(back);
  EXPECT_EQ(back->image.rgb, images(1).image.rgb);  // exactly: 8-bit values survive the PNG
  EXPECT_EQ(back->skin.values, images(1).skin.values);
  EXPECT_FALSE(store.load(marker(2)));
  nlohmann::json other_build = marker(1);
  other_build["build"] = "another";
  EXPECT_FALSE(store.load(other_build));
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
  EXPECT_FALSE(store.load(marker(1)));
  ASSERT_EQ(store.keep(marker(1), images(1)), "");  // kept again over the damaged copy
  EXPECT_TRUE(store.load(marker(1)));
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
  ASSERT_TRUE(store.load(marker(1)));  // used: now the most recent
  tick();
  ASSERT_EQ(store.keep(marker(3), images(3)), "");
  EXPECT_TRUE(store.load(marker(1)));
  EXPECT_FALSE(store.load(marker(2)));  // the least recently used: gone, all three files
  EXPECT_TRUE(store.load(marker(3)));
  EXPECT_EQ(files_in(dir), 6u);
}

TEST(ReferenceStore, AReadOnlyStoreIsNoErrorButSaysWhy) {
  const fs::path dir = fresh_dir("blocked");
  fs::create_directories(dir.parent_path());
  std::ofstream(dir) << "a file where the store's directory would be";
  const ReferenceStore store(dir);
  EXPECT_NE(store.keep(marker(1), images(1)), "");
  EXPECT_FALSE(store.load(marker(1)));
}

TEST(ReferenceStore, TheEnvironmentChoosesTheDirectory) {
  const ScopedEnv xdg("XDG_CACHE_HOME", "/xdg/cache");
  const ScopedEnv home("HOME", "/home/someone");
  {
    const ScopedEnv cache("SKINSIM_CACHE_DIR", "off");
    EXPECT_FALSE(ReferenceStore::from_environment());
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
