#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "gpu_model/device_profile.h"
#include "gpu_model/error.h"
#include "gpu_model/profile_loader.h"
#include "gpu_model/timing_table.h"
#include "test_support.h"

namespace skinsim::gpu_model {
namespace {

using testing::kDataDir;
using testing::parse_error;
using testing::shipped_text;

std::string replace_once(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  if (pos != std::string::npos) text.replace(pos, from.size(), to);
  return text;
}

TEST(Profile, ShippedProfilesLoadAndAreListed) {
  const auto names = list_devices(kDataDir);
  ASSERT_EQ(names, (std::vector<std::string>{"a15", "adreno740", "ipad3", "ipad4", "iphone5",
                                             "mali-g715"}));
  for (const std::string& name : names) {
    const DeviceProfile p = load_device_profile(name, kDataDir);
    EXPECT_EQ(p.name, name);
    EXPECT_FALSE(p.gpu.empty());
    for (const FigureSpec& spec : figure_specs()) {
      const Figure& f = p.*spec.member;
      EXPECT_FALSE(f.source.empty()) << name << " " << spec.path;
      EXPECT_LE(f.min, f.value) << spec.path;
      EXPECT_GE(f.max, f.value) << spec.path;
    }
  }
}

TEST(Profile, Ipad4KeyFigures) {
  const DeviceProfile p = load_device_profile("ipad4", kDataDir);
  EXPECT_EQ(p.gpu, "PowerVR SGX554MP4");
  EXPECT_EQ(p.display_width.value, 2048);
  EXPECT_EQ(p.display_height.value, 1536);
  EXPECT_EQ(p.cores.value, 4);
  EXPECT_EQ(p.pipes_per_core.value, 8);
  EXPECT_EQ(p.clock_mhz.confidence, Confidence::kLow);
  EXPECT_TRUE(p.clock_mhz.has_range);
  EXPECT_DOUBLE_EQ(p.dram_peak_gb_per_s.value, 17.06);
  const SimParameters s = sim_parameters(p);
  EXPECT_EQ(s.tile_width, 32);
  EXPECT_EQ(s.tile_height, 32);
  EXPECT_EQ(s.cores, 4);
  EXPECT_EQ(s.texture_cache_bytes, 8192);
  EXPECT_EQ(s.texture_cache_line_bytes, 64);
  EXPECT_EQ(s.texture_cache_ways, 4);
  EXPECT_FALSE(s.texture_cache_set_hash);  // plain modulo unless a profile says otherwise
}

TEST(Profile, PathAndNameResolveToTheSameFile) {
  const DeviceProfile by_name = load_device_profile("iphone5", kDataDir);
  const DeviceProfile by_path =
      load_device_profile(kDataDir + "/devices/iphone5.toml", "/nonexistent");
  EXPECT_EQ(by_name.display_width.value, by_path.display_width.value);
  EXPECT_EQ(by_path.name, "iphone5");
}

TEST(Profile, UnknownDeviceNamesTheFileAndKnownDevices) {
  try {
    load_device_profile("ipad9", kDataDir);
    FAIL() << "expected ProfileError";
  } catch (const ProfileError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("ipad9.toml"), std::string::npos) << m;
    EXPECT_NE(m.find("ipad4"), std::string::npos) << m;
  }
}

TEST(Profile, ShippedTextParses) {
  EXPECT_EQ(parse_error(shipped_text("ipad4")), "");
}

TEST(Profile, MissingFieldIsNamed) {
  std::string text = shipped_text("ipad4");
  const auto begin = text.find("[isp.hsr_flush_cycles]");
  const auto end = text.find("[overhead.render_cycles]");
  ASSERT_NE(begin, std::string::npos);
  text.erase(begin, end - begin);
  const std::string m = parse_error(text);
  EXPECT_NE(m.find("edited.toml"), std::string::npos) << m;
  EXPECT_NE(m.find("isp.hsr_flush_cycles"), std::string::npos) << m;
  EXPECT_NE(m.find("missing"), std::string::npos) << m;

  const std::string source = parse_error(
      replace_once(shipped_text("ipad4"),
                   "source = \"SGX554MP4: four cores (AnandTech iPad 4 review, GPU page)\"\n", ""));
  EXPECT_NE(source.find("gpu.cores.source"), std::string::npos) << source;
  EXPECT_NE(source.find("missing"), std::string::npos) << source;
}

TEST(Profile, UnknownKeyIsNamed) {
  const std::string m =
      parse_error(replace_once(shipped_text("ipad4"), "[gpu.cores]\n", "[gpu.cores]\nvalu = 4\n"));
  EXPECT_NE(m.find("gpu.cores.valu"), std::string::npos) << m;
  EXPECT_NE(m.find("unknown key"), std::string::npos) << m;

  const std::string section = parse_error(replace_once(shipped_text("ipad4"), "[gpu.cores]\n",
                                                       "[gpu.shader_cores]\nvalue = 4\n"
                                                       "[gpu.cores]\n"));
  EXPECT_NE(section.find("gpu.shader_cores"), std::string::npos) << section;
}

TEST(Profile, WrongTypeIsNamed) {
  const std::string m = parse_error(replace_once(
      shipped_text("ipad4"), "[gpu.clock_mhz]\nvalue = 300.0", "[gpu.clock_mhz]\nvalue = \"300\""));
  EXPECT_NE(m.find("gpu.clock_mhz.value"), std::string::npos) << m;
  EXPECT_NE(m.find("must be a number, got string"), std::string::npos) << m;

  const std::string bare =
      parse_error(replace_once(shipped_text("ipad4"),
                               "[gpu.cores]\nvalue = 4\nconfidence = \"certain\"\nsource = "
                               "\"SGX554MP4: four cores (AnandTech iPad 4 review, GPU page)\"\n",
                               "[gpu]\ncores = 4\n"));
  EXPECT_NE(bare.find("field 'gpu.cores'"), std::string::npos) << bare;
  EXPECT_NE(bare.find("must be a table with value"), std::string::npos) << bare;
}

TEST(Profile, NonPositiveRateIsNamed) {
  const std::string m = parse_error(
      replace_once(shipped_text("ipad4"), "[isp.fragments_per_clock_per_core]\nvalue = 16.0",
                   "[isp.fragments_per_clock_per_core]\nvalue = -16.0"));
  EXPECT_NE(m.find("isp.fragments_per_clock_per_core.value"), std::string::npos) << m;
  EXPECT_NE(m.find("must be a number in [0.001, 1024] frag/clk, got -16"), std::string::npos) << m;
  const std::string zero = parse_error(
      replace_once(shipped_text("ipad4"), "[gpu.clock_mhz]\nvalue = 300.0\nrange = [280.0, 300.0]",
                   "[gpu.clock_mhz]\nvalue = 0\nrange = [0, 300.0]"));
  EXPECT_NE(zero.find("gpu.clock_mhz.value"), std::string::npos) << zero;
}

TEST(Profile, FractionOutsideUnitIntervalIsNamed) {
  const std::string m = parse_error(replace_once(
      shipped_text("ipad4"), "[memory.achievable_fraction]\nvalue = 0.6\nrange = [0.4, 0.8]",
      "[memory.achievable_fraction]\nvalue = 1.5\nrange = [0.4, 1.8]"));
  EXPECT_NE(m.find("memory.achievable_fraction.value"), std::string::npos) << m;
  EXPECT_NE(m.find("must be a number in [0.01, 1], got 1.5"), std::string::npos) << m;
}

TEST(Profile, NonIntegerCountIsNamed) {
  const std::string m = parse_error(
      replace_once(shipped_text("ipad4"), "[gpu.cores]\nvalue = 4", "[gpu.cores]\nvalue = 3.5"));
  EXPECT_NE(m.find("gpu.cores.value"), std::string::npos) << m;
  EXPECT_NE(m.find("must be an integer in [1, 64] cores, got 3.5"), std::string::npos) << m;
}

TEST(Profile, RangeMustContainValueAndIsRequiredWhenLowConfidence) {
  const std::string outside = parse_error(
      replace_once(shipped_text("ipad4"), "range = [280.0, 300.0]", "range = [200.0, 250.0]"));
  EXPECT_NE(outside.find("gpu.clock_mhz.range"), std::string::npos) << outside;

  const std::string missing =
      parse_error(replace_once(shipped_text("ipad4"), "range = [280.0, 300.0]\n", ""));
  EXPECT_NE(missing.find("gpu.clock_mhz.range"), std::string::npos) << missing;
  EXPECT_NE(missing.find("confidence is low"), std::string::npos) << missing;
}

TEST(Profile, CacheSizeMustHoldWholeSets) {
  const std::string m =
      parse_error(replace_once(shipped_text("ipad4"), "[texture.cache_bytes]\nvalue = 8192",
                               "[texture.cache_bytes]\nvalue = 8000"));
  EXPECT_NE(m.find("texture.cache_bytes"), std::string::npos) << m;
  EXPECT_NE(m.find("multiple"), std::string::npos) << m;
}

TEST(Profile, CacheSetHashMustBeGivenAndZeroOrOne) {
  const std::string hash_block = "[texture.cache_set_hash]\nvalue = 0\n";
  const std::string text = shipped_text("ipad4");
  const std::string block =
      text.substr(text.find(hash_block), text.find("[tile.width]") - text.find(hash_block));
  const std::string missing = parse_error(replace_once(text, block, ""));
  EXPECT_NE(missing.find("edited.toml: field 'texture.cache_set_hash': missing"), std::string::npos)
      << missing;

  for (const char* bad : {"0.5", "2"}) {
    const std::string m = parse_error(replace_once(
        text, hash_block, "[texture.cache_set_hash]\nvalue = " + std::string(bad) + "\n"));
    EXPECT_NE(m.find("edited.toml:"), std::string::npos) << m;
    EXPECT_NE(m.find("'texture.cache_set_hash.value': must be an integer in [0, 1]"),
              std::string::npos)
        << m;
  }

  const DeviceProfile hashed = parse_device_profile(
      replace_once(text, hash_block, "[texture.cache_set_hash]\nvalue = 1\n"), "edited.toml");
  EXPECT_TRUE(sim_parameters(hashed).texture_cache_set_hash);
}

TEST(Profile, CacheSetHashNeedsPowerOfTwoSets) {
  // 12288 B / (64 B x 4 ways) = 48 sets: fine for modulo, but the range sweeps hashing too.
  const std::string text =
      replace_once(shipped_text("ipad4"), "[texture.cache_bytes]\nvalue = 8192",
                   "[texture.cache_bytes]\nvalue = 12288");
  const std::string m = parse_error(text);
  EXPECT_NE(m.find("'texture.cache_set_hash.range[1]'"), std::string::npos) << m;
  EXPECT_NE(m.find("48 sets"), std::string::npos) << m;
  EXPECT_EQ(
      parse_error(replace_once(text, "value = 0\nrange = [0, 1]", "value = 0\nrange = [0, 0]")),
      "");
}

TEST(Profile, BadConfidenceAndSyntaxAreReported) {
  const std::string conf = parse_error(
      replace_once(shipped_text("ipad4"), "confidence = \"certain\"", "confidence = \"sure\""));
  EXPECT_NE(conf.find("display.width.confidence"), std::string::npos) << conf;

  const std::string syntax = parse_error("[gpu\nvalue = 1\n");
  EXPECT_NE(syntax.find("edited.toml:1"), std::string::npos) << syntax;
  EXPECT_NE(syntax.find("TOML syntax error"), std::string::npos) << syntax;
}

TEST(Profile, DeviceTableListsShippedProfiles) {
  const DeviceCatalog catalog = load_device_catalog(kDataDir);
  EXPECT_TRUE(catalog.problems.empty());
  const std::string table = format_device_table(catalog.profiles);
  for (const char* text : {"ipad3", "ipad4", "iphone5", "SGX554MP4", "SGX543MP3", "2048x1536",
                           "1136x640", "4x8", "76.8"}) {
    EXPECT_NE(table.find(text), std::string::npos) << text << "\n" << table;
  }
}

TEST(Profile, CatalogKeepsGoodProfilesAndReportsEachBrokenOne) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "skinsim_profile_catalog";
  fs::remove_all(dir);
  fs::create_directories(dir / "devices");
  fs::copy_file(kDataDir + "/devices/ipad4.toml", dir / "devices" / "ipad4.toml");
  std::ofstream(dir / "devices" / "a_broken.toml")
      << replace_once(shipped_text("ipad4"), "[gpu.cores]\nvalue = 4", "[gpu.cores]\nvalue = 65");
  std::ofstream(dir / "devices" / "z_syntax.toml") << "[gpu\n";
  fs::create_directories(dir / "devices" / "dir.toml");  // not a regular file: not listed

  const DeviceCatalog catalog = load_device_catalog(dir.string());
  ASSERT_EQ(catalog.profiles.size(), 1u);
  EXPECT_EQ(catalog.profiles[0].name, "ipad4");
  ASSERT_EQ(catalog.problems.size(), 2u);
  EXPECT_NE(catalog.problems[0].find("a_broken.toml"), std::string::npos) << catalog.problems[0];
  EXPECT_NE(catalog.problems[0].find("'gpu.cores.value'"), std::string::npos);
  EXPECT_NE(catalog.problems[1].find("z_syntax.toml"), std::string::npos) << catalog.problems[1];
  fs::remove_all(dir);
}

}  // namespace
}  // namespace skinsim::gpu_model
