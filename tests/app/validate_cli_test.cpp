// `skinsim validate` end to end: the real binary on a small frame. The expected figures come
// from `skinsim run`'s result.json for the same configuration, not from validate's code: the
// printed and written errors must be measured minus result.json's ms, and the frame's range
// must be result.json's frame_ms_range. Bad CSVs exit 2 naming the file and line.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tests/app/run_skinsim.h"

namespace {

namespace fs = std::filesystem;

using skinsim::test::Result;
using skinsim::test::run;

// The configuration both commands model: small, so the test is quick.
const std::string kConfig = " --resolution 256x192 --texture-size 128 --threads 2";

fs::path validate_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("skinsim_validate_cli_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  return nlohmann::json::parse(in);
}

// A signed difference as the table prints it: one that rounds to zero is +0.
std::string printed(double value, int decimals) {
  std::string text = fmt::format("{:+.{}f}", value, decimals);
  if (text.find_first_not_of("+-0.") == std::string::npos) text[0] = '+';
  return text;
}

// The printed table's line for `name` ("" when there is none).
std::string table_line(const std::string& output, const std::string& name) {
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(name + " ", 0) == 0) return line;
  }
  return "";
}

// Each test runs in its own process under ctest: its own directory and run.
class ValidateCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = validate_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    const Result r = run("run --no-reference --out " + (dir_ / "run").string() + kConfig);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    result_ = read_json(dir_ / "run" / "result.json");
  }
  fs::path dir_;
  nlohmann::json result_;
};

TEST_F(ValidateCli, ErrorsAreMeasuredMinusTheRunsModelledMs) {
  const nlohmann::json& passes = result_["timing"]["passes"];
  ASSERT_GE(passes.size(), 3u);
  ASSERT_EQ(result_["timing"]["dram_wait_ms"].get<double>(), 0.0);
  // Known measurements, unrelated to the model: 0.5, 0.75, 1.0, ... ms.
  const fs::path csv = dir_ / "measured.csv";
  {
    std::ofstream out(csv);
    out << "# a test's measurements, not a device's\npass,ms\n";
    for (std::size_t i = 0; i < passes.size(); ++i) {
      out << passes[i]["name"].get<std::string>() << "," << 0.5 + 0.25 * i << "\n";
    }
  }
  const fs::path json_path = dir_ / "validation.json";
  const Result r = run("validate " + csv.string() + kConfig + " --json " + json_path.string());
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.output;
  const nlohmann::json v = read_json(json_path);
  ASSERT_EQ(v["rows"].size(), passes.size());
  double measured_sum = 0.0;
  bool any_outside = false;
  for (std::size_t i = 0; i < passes.size(); ++i) {
    const std::string name = passes[i]["name"];
    const double measured = 0.5 + 0.25 * i;
    const double model = passes[i]["ms"];
    measured_sum += measured;
    const nlohmann::json& row = v["rows"][i];
    EXPECT_EQ(row["name"], name);
    EXPECT_EQ(row["line"], static_cast<int>(i) + 3);
    EXPECT_NEAR(row["model_ms"].get<double>(), model, 1e-12) << name;
    EXPECT_NEAR(row["measured_ms"].get<double>(), measured, 1e-12) << name;
    EXPECT_NEAR(row["error_ms"].get<double>(), measured - model, 1e-12) << name;
    EXPECT_NEAR(row["error_percent"].get<double>(), 100.0 * (measured - model) / model, 1e-9);
    EXPECT_LE(row["model_low_ms"].get<double>(), model);
    EXPECT_GE(row["model_high_ms"].get<double>(), model);
    const bool inside = measured >= row["model_low_ms"].get<double>() - 0.0005 &&
                        measured <= row["model_high_ms"].get<double>() + 0.0005;
    EXPECT_EQ(row["inside_range"], inside) << name;
    any_outside = any_outside || !inside;
    const std::string line = table_line(r.output, name);
    EXPECT_NE(line.find(printed(measured - model, 3)), std::string::npos) << name << "\n"
                                                                          << r.output;
    EXPECT_NE(line.find(printed(100.0 * (measured - model) / model, 1)), std::string::npos)
        << name << "\n"
        << r.output;
    EXPECT_NE(line.find(inside ? " yes " : " NO "), std::string::npos) << line;
  }
  // The frame: the sum of the measured passes against result.json's frame and its range.
  const double frame_ms = result_["timing"]["frame_ms"];
  const nlohmann::json& range = result_["timing"]["frame_ms_range"];
  const nlohmann::json& frame = v["frame"];
  EXPECT_NEAR(frame["measured_ms"].get<double>(), measured_sum, 1e-12);
  EXPECT_NEAR(frame["model_ms"].get<double>(), frame_ms, 1e-12);
  EXPECT_NEAR(frame["model_low_ms"].get<double>(), range["low"].get<double>(), 1e-12);
  EXPECT_NEAR(frame["model_high_ms"].get<double>(), range["high"].get<double>(), 1e-12);
  EXPECT_NEAR(frame["error_ms"].get<double>(), measured_sum - frame_ms, 1e-12);
  const bool frame_inside = measured_sum >= range["low"].get<double>() - 0.0005 &&
                            measured_sum <= range["high"].get<double>() + 0.0005;
  EXPECT_EQ(frame["inside_range"], frame_inside);
  any_outside = any_outside || !frame_inside;
  EXPECT_NE(table_line(r.output, "frame").find(printed(measured_sum - frame_ms, 3)),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.exit_code, any_outside ? 1 : 0) << r.output;
  EXPECT_EQ(v["device"], "ipad4");
}

TEST_F(ValidateCli, TheModelsOwnTimesAreInsideAndExitZero) {
  const nlohmann::json& passes = result_["timing"]["passes"];
  const fs::path csv = dir_ / "model.csv";
  {
    std::ofstream out(csv);
    for (const nlohmann::json& p : passes) {
      out << p["name"].get<std::string>() << "," << fmt::format("{:.4f}", p["ms"].get<double>())
          << "\n";
    }
    out << "frame," << fmt::format("{:.4f}", result_["timing"]["frame_ms"].get<double>()) << "\n";
  }
  const Result r = run("validate " + csv.string() + kConfig);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const std::string verdict = fmt::format("{0} of {0} compared rows inside", passes.size() + 1);
  EXPECT_NE(r.output.find(verdict), std::string::npos) << r.output;

  // The same frame measured at twice the model's time is outside somewhere: exit 1.
  std::ofstream(dir_ / "slow.csv")
      << "frame," << 4.0 * result_["timing"]["frame_ms_range"]["high"].get<double>() << "\n";
  const Result slow = run("validate " + (dir_ / "slow.csv").string() + kConfig);
  EXPECT_EQ(slow.exit_code, 1) << slow.output;
  EXPECT_NE(slow.output.find("the frame is OUTSIDE its range"), std::string::npos) << slow.output;
}

TEST_F(ValidateCli, BadMeasurementsExitTwoNamingFileAndLine) {
  const fs::path& dir = dir_;
  const auto expect_bad = [&](const std::string& name, const std::string& text,
                              const std::string& message) {
    const fs::path csv = dir / name;
    std::ofstream(csv) << text;
    const Result r = run("validate " + csv.string() + kConfig);
    EXPECT_EQ(r.exit_code, 2) << name << ": " << r.output;
    EXPECT_NE(r.output.find(csv.string() + message), std::string::npos) << name << ": " << r.output;
    EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
  };
  expect_bad("negative.csv", "# c\nshadow,1\nskin,-2\n",
             ":3: field 'ms': a time cannot be negative");
  expect_bad("number.csv", "skin,1.2.3\n", ":1: field 'ms': expected a plain decimal number");
  expect_bad("duplicate.csv", "skin,1\nskin,2\n", ":2: field 'pass': 'skin' is measured twice");
  expect_bad("unknown.csv", "shadow,1\nskni,2\n",
             ":2: field 'pass': 'skni' is not a pass of the modelled frame");
  expect_bad("empty.csv", "", ": no measurements");

  const Result missing = run("validate " + (dir / "missing.csv").string() + kConfig);
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_NE(missing.output.find((dir / "missing.csv").string()), std::string::npos);
  const Result no_file = run("validate" + kConfig);
  EXPECT_EQ(no_file.exit_code, 2) << no_file.output;
  // The run's knobs are validated as for `run`.
  std::ofstream(dir / "ok.csv") << "skin,1\n";
  const Result knob = run("validate " + (dir / "ok.csv").string() + " --scale 2");
  EXPECT_EQ(knob.exit_code, 2) << knob.output;
  EXPECT_NE(knob.output.find("scale must be in (0, 1], got 2"), std::string::npos) << knob.output;
}

TEST_F(ValidateCli, UnknownPassesCanBeListedAndMissingOnesAreNamed) {
  const fs::path csv = dir_ / "partial.csv";
  std::ofstream(csv) << "skin,1\nui_overlay,0.4\n";
  const Result r = run("validate " + csv.string() + kConfig + " --allow-unknown-passes");
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.output;
  EXPECT_NE(r.output.find("not in the model (measured in " + csv.string() +
                          ", not a pass of this frame): ui_overlay (line 2)"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("not measured (in the model, no line in " + csv.string() + "): shadow"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("the frame is not compared"), std::string::npos) << r.output;
}

}  // namespace
