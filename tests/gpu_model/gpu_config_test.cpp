#include "gpu_model/gpu_config.h"

#include <gtest/gtest.h>

#include "gpu_model/error.h"
#include "gpu_model/profile_loader.h"
#include "test_support.h"

namespace skinsim::gpu_model {
namespace {

TEST(GpuConfig, CarriesTheProfileEmulatorFigures) {
  DeviceProfile p = load_device_profile("ipad4", testing::kDataDir);
  sim::GpuConfig c = gpu_config(p, 3);
  EXPECT_EQ(c.tile_size, 32);
  EXPECT_EQ(c.cores, 4);
  EXPECT_EQ(c.texture_cache.size_bytes, 8192u);
  EXPECT_EQ(c.texture_cache.line_bytes, 64u);
  EXPECT_EQ(c.texture_cache.associativity, 4u);
  EXPECT_EQ(c.texture_cache.set_index, sim::SetIndex::kModulo);
  EXPECT_EQ(c.threads, 3);

  p.texture_cache_set_hash.value = 1;
  EXPECT_EQ(gpu_config(p, 1).texture_cache.set_index, sim::SetIndex::kXorFold);
}

TEST(GpuConfig, RejectsNonSquareTilesNamingTheFields) {
  DeviceProfile p = load_device_profile("ipad4", testing::kDataDir);
  p.tile_height.value = 16;
  try {
    gpu_config(p, 1);
    FAIL() << "expected ProfileError";
  } catch (const ProfileError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("ipad4.toml"), std::string::npos) << m;
    EXPECT_NE(m.find("'tile.height' (16)"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace skinsim::gpu_model
