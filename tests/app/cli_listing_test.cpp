// The listing commands and the messages a user meets first, consistent with each other: knobs
// name their options, an unknown option gets the close one, --set matches the knob's option,
// techniques list the shadow pass that run times, devices explain their columns and print
// JSON, compare prints bytes in MB, and --sensitivity puts the largest swing first.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/app/run_skinsim.h"
#include "tests/text_lines.h"

namespace {

using skinsim::test::Result;
using skinsim::test::run;

const std::string kSmall = " --resolution 64x48 --no-reference";

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("skinsim_listing_" + name);
  std::filesystem::remove_all(dir);
  return dir;
}

nlohmann::json read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

using skinsim::testing::lines_of;

TEST(CliListing, KnobsNameEveryOption) {
  Result plain = run("knobs");
  plain.output.insert(0, "\n");  // each row then starts after a newline
  const Result json = run("knobs --json");
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  ASSERT_EQ(json.exit_code, 0) << json.output;
  for (const auto& knob : nlohmann::json::parse(json.output)) {
    const std::string row = knob["name"].get<std::string>();
    const auto at = plain.output.find("\n" + row + " ");
    ASSERT_NE(at, std::string::npos) << row;
    const std::string line = plain.output.substr(at + 1, plain.output.find('\n', at + 1) - at);
    EXPECT_NE(line.find(" " + knob["option"].get<std::string>() + " "), std::string::npos) << line;
  }
}

// `skinsim ARGS` exits 2 and says `message`.
void expect_refused(const std::string& args, const std::string& message) {
  const Result r = run(args);
  EXPECT_EQ(r.exit_code, 2) << args;
  EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
}

TEST(CliListing, UnknownOptionGetsTheCloseOne) {
  expect_refused("run --light_azimuth_deg 60",
                 "unknown option --light_azimuth_deg; did you mean --light-azimuth (knob "
                 "light_azimuth_deg; or --set light_azimuth_deg=VALUE)?");
  expect_refused("sweep --sweep_file x.toml", "did you mean --sweep-file?");
  expect_refused("run --scael 0.5", "did you mean --scale?");
  expect_refused("run --completely-unknown=3",
                 "unknown option --completely-unknown (`skinsim run --help` lists");
}

TEST(CliListing, RunSetIsTheKnobsOption) {
  const auto by_set = fresh_dir("set");
  const auto by_option = fresh_dir("option");
  ASSERT_EQ(
      run("run --set scale=0.25 --set light_azimuth_deg=60" + kSmall + " --out " + by_set.string())
          .exit_code,
      0);
  ASSERT_EQ(run("run --scale 0.25 --light-azimuth 60" + kSmall + " --out " + by_option.string())
                .exit_code,
            0);
  const nlohmann::json a = read_json(by_set / "result.json");
  const nlohmann::json b = read_json(by_option / "result.json");
  EXPECT_EQ(a["config"], b["config"]);
  EXPECT_EQ(a["timing"], b["timing"]);

  expect_refused("run --set scale=0.25 --scale 0.5" + kSmall,
                 "--set scale=0.25: --scale is given too");
  expect_refused("run --set no_such_knob=1" + kSmall, "no_such_knob");
  expect_refused("run --set scale" + kSmall, "--set: expected knob=value, got 'scale'");
  expect_refused("run --set scale=2" + kSmall, "scale must be in (0, 1], got 2");
}

TEST(CliListing, TechniquesListThePassesRunTimes) {
  const Result techniques = run("techniques --json");
  ASSERT_EQ(techniques.exit_code, 0) << techniques.output;
  for (const auto& technique : nlohmann::json::parse(techniques.output)) {
    const std::string name = technique["name"].get<std::string>();
    const auto dir = fresh_dir("technique");
    ASSERT_EQ(run("run --technique " + name + kSmall + " --out " + dir.string()).exit_code, 0)
        << name;
    const nlohmann::json result = read_json(dir / "result.json");
    std::string timed;
    for (const auto& pass : result["timing"]["passes"]) {
      timed += (timed.empty() ? "" : ", ") + pass["name"].get<std::string>();
    }
    const std::string listed = technique["passes"].get<std::string>();
    if (listed.find('{') == std::string::npos) {
      EXPECT_EQ(listed, timed) << name;
    } else {  // a pattern such as uv_blur_{1..5}_{h,v}: the ends still match
      EXPECT_EQ(listed.substr(0, listed.find(", ")), timed.substr(0, timed.find(", "))) << name;
      EXPECT_EQ(listed.substr(listed.rfind(", ")), timed.substr(timed.rfind(", "))) << name;
    }
  }
  EXPECT_NE(run("techniques").output.find("passes: shadow, irradiance"), std::string::npos);
}

TEST(CliListing, DevicesExplainTheirColumnsAndPrintJson) {
  const Result table = run("devices");
  ASSERT_EQ(table.exit_code, 0) << table.output;
  EXPECT_NE(table.output.find("GFLOPS = peak FP32"), std::string::npos) << table.output;
  EXPECT_NE(table.output.find("tex$ KiB = texture cache per core"), std::string::npos);
  const Result json = run("devices --json");
  ASSERT_EQ(json.exit_code, 0) << json.output;
  const nlohmann::json devices = nlohmann::json::parse(json.output);
  ASSERT_EQ(devices.size(), 6u);
  EXPECT_NE(table.output.find("class = tbdr | tiler-early-z | binning"), std::string::npos);
  for (const auto& d : devices) {
    EXPECT_NE(table.output.find("\n" + d["name"].get<std::string>() + " "), std::string::npos);
    if (d["name"] == "ipad4") {  // 4 cores x 8 pipes x 8 FLOP x 300 MHz
      EXPECT_DOUBLE_EQ(d["peak_gflops"].get<double>(), 76.8);
      EXPECT_EQ(d["display"], nlohmann::json::array({2048, 1536}));
      EXPECT_EQ(d["class"], "tbdr");
    }
    if (d["name"] == "mali-g715") {  // 256 bits per pixel at 16x16: 32 B fits, FP16 at 2x
      EXPECT_EQ(d["class"], "tiler-early-z");
      EXPECT_EQ(d["tile_at_32_bytes_per_pixel"], nlohmann::json::array({16, 16}));
      EXPECT_DOUBLE_EQ(d["fp16_rate"].get<double>(), 2.0);
    }
  }
}

TEST(CliListing, CompareShowsBytesInMegabytes) {
  const auto a = fresh_dir("compare_a");
  const auto b = fresh_dir("compare_b");
  ASSERT_EQ(run("run" + kSmall + " --out " + a.string()).exit_code, 0);
  ASSERT_EQ(run("run --scale 0.25" + kSmall + " --out " + b.string()).exit_code, 0);
  const Result r = run("compare " + a.string() + " " + b.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  bool bytes_row = false;
  for (const std::string& line :
       lines_of(r.output)) {  // e.g. "timing.dram_bytes", "...bytes.texture"
    if (!line.starts_with("  ") ||
        line.substr(0, line.find_first_of(' ', 2)).find("bytes") == std::string::npos) {
      continue;
    }
    bytes_row = true;
    EXPECT_NE(line.find(" MB "), std::string::npos) << line;
    EXPECT_EQ(line.find("e+"), std::string::npos) << line;
  }
  EXPECT_TRUE(bytes_row) << r.output;
}

TEST(CliListing, SensitivityPutsTheLargestSwingFirst) {
  const Result r = run("run --sensitivity" + kSmall + " --out " + fresh_dir("sens").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::vector<std::string> lines = lines_of(r.output);
  auto header = std::find_if(lines.begin(), lines.end(), [](const std::string& l) {
    return l.starts_with("figure") && l.ends_with("swing ms");
  });
  ASSERT_NE(header, lines.end()) << r.output;
  double previous = 1e300;
  int rows = 0;
  for (auto it = header + 1; it != lines.end() && !it->starts_with("swing ms ="); ++it) {
    const std::string swing = it->substr(it->find_last_of(' ') + 1);
    const double value = std::stod(swing);  // every figure is re-rendered: none is "re-run"
    EXPECT_LE(value, previous) << *it;
    previous = value;
    ++rows;
  }
  EXPECT_GT(rows, 10);
}

}  // namespace
