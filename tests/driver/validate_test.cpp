// `skinsim validate`'s measurement CSV and its comparison with a modelled frame: parsing (good
// files, each kind of bad line named by file, line and field), the error and in-range maths on
// a hand-made frame, and the per-row ranges on synthetic counters. No rendering.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "driver/validate/validate_compare.h"
#include "driver/validate/validate_measurements.h"
#include "gpu_model/frame_cost.h"
#include "io/read_file.h"
#include "tests/gpu_model/test_support.h"
#include "tests/test_paths.h"

namespace skinsim::driver {
namespace {

// The message parse_measurements throws for `text`, or "" when it parses.
std::string parse_error(const std::string& text) {
  try {
    parse_measurements(text, "m.csv");
  } catch (const MeasurementError& e) {
    return e.what();
  }
  return "";
}

TEST(ValidateParse, ReadsRowsCommentsHeaderFrameAndCrlf) {
  const Measurements m = parse_measurements(
      "# device: ipad4, technique mobile, 2048x1536\r\n"
      "\n"
      "pass,ms\r\n"
      "shadow,1.5\r\n"
      "  irradiance ,\t0.25 \n"
      "   # an indented comment\n"
      "frame,12\n"
      "skin,1e-1",  // no final newline
      "m.csv");
  EXPECT_EQ(m.file, "m.csv");
  ASSERT_EQ(m.passes.size(), 3u);
  EXPECT_EQ(m.passes[0].name, "shadow");
  EXPECT_DOUBLE_EQ(m.passes[0].ms, 1.5);
  EXPECT_EQ(m.passes[0].line, 4);
  EXPECT_EQ(m.passes[1].name, "irradiance");
  EXPECT_DOUBLE_EQ(m.passes[1].ms, 0.25);
  EXPECT_EQ(m.passes[1].line, 5);
  EXPECT_EQ(m.passes[2].name, "skin");
  EXPECT_DOUBLE_EQ(m.passes[2].ms, 0.1);
  EXPECT_EQ(m.passes[2].line, 8);
  ASSERT_TRUE(m.frame.has_value());
  EXPECT_DOUBLE_EQ(m.frame->ms, 12.0);
  EXPECT_EQ(m.frame->line, 7);
}

TEST(ValidateParse, ZeroIsAMeasurementAndTheHeaderIsOptional) {
  const Measurements m = parse_measurements("blur_h,0\n", "m.csv");
  ASSERT_EQ(m.passes.size(), 1u);
  EXPECT_EQ(m.passes[0].ms, 0.0);
  EXPECT_FALSE(m.frame.has_value());
  const Measurements only_frame = parse_measurements("frame,33.3\n", "m.csv");
  EXPECT_TRUE(only_frame.passes.empty());
  ASSERT_TRUE(only_frame.frame.has_value());
}

TEST(ValidateParse, BadNumbersNameTheLineAndField) {
  for (const char* bad : {"abc", "nan", "inf", "0x10", "1,5", "1e999", "--1", "1 2"}) {
    const std::string text = std::string("pass,ms\nshadow,1\nskin,") + bad + "\n";
    const std::string e = parse_error(text);
    if (std::string(bad) == "1,5") {  // a third field
      EXPECT_NE(e.find("m.csv:3: expected two fields"), std::string::npos) << e;
      continue;
    }
    EXPECT_NE(e.find("m.csv:3: field 'ms': expected a plain decimal number"), std::string::npos)
        << bad << ": " << e;
  }
  EXPECT_NE(parse_error("skin,\n").find("m.csv:1: field 'ms': is empty"), std::string::npos);
}

TEST(ValidateParse, NegativeTimeIsRefused) {
  const std::string e = parse_error("# c\nskin,-0.5\n");
  EXPECT_NE(e.find("m.csv:2: field 'ms': a time cannot be negative, got -0.5 for pass 'skin'"),
            std::string::npos)
      << e;
}

TEST(ValidateParse, DuplicatePassNamesBothLines) {
  const std::string e = parse_error("skin,1\nshadow,2\nskin,3\n");
  EXPECT_NE(e.find("m.csv:3: field 'pass': 'skin' is measured twice (first on line 1)"),
            std::string::npos)
      << e;
  const std::string frame = parse_error("frame,1\nframe,2\n");
  EXPECT_NE(frame.find("m.csv:2: field 'pass': 'frame' is measured twice (first on line 1)"),
            std::string::npos)
      << frame;
}

TEST(ValidateParse, EmptyFilesAndCommentOnlyFilesAreRefused) {
  for (const char* text : {"", "\n\n", "# only a comment\n", "pass,ms\n"}) {
    const std::string e = parse_error(text);
    EXPECT_NE(e.find("m.csv: no measurements"), std::string::npos) << e;
  }
}

TEST(ValidateParse, MalformedLinesNameTheLine) {
  EXPECT_NE(parse_error("skin 1\n").find("m.csv:1: expected two fields 'pass,ms' separated"),
            std::string::npos);
  EXPECT_NE(parse_error("skin,1\n\"shadow\",2\n").find("m.csv:2: quoted fields"),
            std::string::npos);
  EXPECT_NE(parse_error(",1\n").find("m.csv:1: field 'pass': is empty"), std::string::npos);
  EXPECT_NE(parse_error("sk in,1\n").find("m.csv:1: field 'pass': 'sk in' is not a pass name"),
            std::string::npos);
  EXPECT_NE(parse_error("skin,1\npass,ms\n").find("m.csv:2: field 'pass': the 'pass,ms' header"),
            std::string::npos);
  EXPECT_NE(parse_error("pass,time\n").find("m.csv:1: field 'ms': the header must be 'pass,ms'"),
            std::string::npos);
  EXPECT_NE(parse_error(std::string("skin,1\n\x01\xff,2\n"))
                .find("m.csv:2: field 'pass': '\\x01\\xff' is not a pass name"),
            std::string::npos);
  EXPECT_NE(parse_error(std::string("skin,1\0", 7)).find("m.csv:1: holds a NUL byte"),
            std::string::npos);
}

TEST(ValidateParse, MissingFileOrDirectoryIsAnInputError) {
  EXPECT_THROW(read_measurements("/nonexistent/measured.csv"), io::InputError);
  EXPECT_THROW(read_measurements(std::filesystem::temp_directory_path()), io::InputError);
  const auto path = std::filesystem::temp_directory_path() / "skinsim_validate_test.csv";
  std::ofstream(path) << "skin,2\nskin,x\n";
  try {
    read_measurements(path);
    FAIL() << "expected a MeasurementError";
  } catch (const MeasurementError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string() + ":2: field 'ms'"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove(path);
}

// A frame of two passes, a (2 ms) and b (3 ms), with hand-picked ranges.
struct HandFrame {
  gpu_model::FrameTiming timing;
  std::vector<ModelledMs> rows;
  gpu_model::FrameMsRange range;

  HandFrame() {
    timing.device = "hand";
    timing.passes.resize(2);
    timing.passes[0].name = "a";
    timing.passes[0].bottleneck = gpu_model::Unit::kAlu;
    timing.passes[1].name = "b";
    timing.passes[1].bottleneck = gpu_model::Unit::kTexture;
    timing.schedule.resize(2);
    timing.schedule[0].exposed_ms = 2.0;
    timing.schedule[1].exposed_ms = 3.0;
    timing.frame_ms = 5.0;
    rows = {{2.0, 1.0, 4.0}, {3.0, 2.5, 3.5}};
    range.base = 5.0;
    range.low = 3.5;
    range.high = 7.5;
    range.figures = 19;
    range.left_out = 4;
  }

  Validation compare(const std::string& csv, const ValidateOptions& options = {}) const {
    return compare_measurements(parse_measurements(csv, "m.csv"), timing, rows, range, options);
  }
};

TEST(ValidateCompare, ErrorIsMeasuredMinusModelAndRangesDecideInside) {
  const HandFrame f;
  const Validation v = f.compare("a,2.5\nb,4\n");
  ASSERT_EQ(v.rows.size(), 2u);
  const ValidationRow& a = v.rows[0];
  EXPECT_EQ(a.name, "a");
  EXPECT_EQ(a.bottleneck, "alu");
  EXPECT_EQ(a.line, 1);
  EXPECT_DOUBLE_EQ(a.error_ms(), 0.5);
  EXPECT_DOUBLE_EQ(*a.error_percent(), 25.0);
  EXPECT_TRUE(a.inside());  // 2.5 in [1, 4]
  const ValidationRow& b = v.rows[1];
  EXPECT_DOUBLE_EQ(b.error_ms(), 1.0);
  EXPECT_DOUBLE_EQ(*b.error_percent(), 100.0 / 3.0);
  EXPECT_FALSE(b.inside());  // 4 > 3.5
  // Every pass measured, no frame row: the frame is their sum.
  EXPECT_TRUE(v.frame.measured_sum);
  EXPECT_DOUBLE_EQ(*v.frame.measured_ms, 6.5);
  EXPECT_DOUBLE_EQ(v.frame.error_ms(), 1.5);
  EXPECT_DOUBLE_EQ(*v.frame.error_percent(), 30.0);
  EXPECT_TRUE(v.frame.inside());  // 6.5 in [3.5, 7.5]
  EXPECT_EQ(v.compared(), 3);
  EXPECT_EQ(v.outside(), 1);
  EXPECT_TRUE(v.not_measured.empty());
  EXPECT_TRUE(v.not_modelled.empty());

  const std::string table = format_validation(v);
  EXPECT_NE(table.find("+0.500"), std::string::npos) << table;
  EXPECT_NE(table.find("+25.0"), std::string::npos) << table;
  EXPECT_NE(table.find("+33.3"), std::string::npos) << table;
  EXPECT_NE(table.find("NO"), std::string::npos) << table;
  EXPECT_NE(table.find("2 of 3 compared rows inside"), std::string::npos) << table;
  EXPECT_NE(table.find("6.500*"), std::string::npos) << table;

  const nlohmann::json j = to_json(v);
  EXPECT_EQ(j["outside_range"], 1);
  EXPECT_EQ(j["rows"][1]["inside_range"], false);
  EXPECT_DOUBLE_EQ(j["rows"][0]["error_ms"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(j["frame"]["model_low_ms"].get<double>(), 3.5);
  EXPECT_EQ(j["frame"]["measured_from"], "sum of the measured passes");
}

TEST(ValidateCompare, RangeEdgesCountWithinHalfTheLastPrintedDigit) {
  const HandFrame f;
  EXPECT_TRUE(f.compare("b,3.5004\n").rows[1].inside());
  EXPECT_FALSE(f.compare("b,3.5006\n").rows[1].inside());
  EXPECT_TRUE(f.compare("b,2.4996\n").rows[1].inside());
  EXPECT_FALSE(f.compare("b,2.4994\n").rows[1].inside());
}

TEST(ValidateCompare, FrameRowWinsAndMissingPassesAreNamed) {
  const HandFrame f;
  const Validation v = f.compare("frame,8\na,2\n");
  EXPECT_EQ(v.not_measured, std::vector<std::string>{"b"});
  EXPECT_FALSE(v.frame.measured_sum);
  EXPECT_EQ(v.frame.line, 1);
  EXPECT_DOUBLE_EQ(v.frame.error_ms(), 3.0);
  EXPECT_FALSE(v.frame.inside());  // 8 > 7.5
  EXPECT_FALSE(v.rows[1].compared());
  EXPECT_EQ(v.compared(), 2);
  const std::string table = format_validation(v);
  EXPECT_NE(table.find("not measured (in the model, no line in m.csv): b"), std::string::npos)
      << table;

  // Neither a frame row nor every pass: the frame is not compared.
  const Validation partial = f.compare("a,2\n");
  EXPECT_FALSE(partial.frame.compared());
  EXPECT_NE(format_validation(partial).find("the frame is not compared"), std::string::npos);
}

TEST(ValidateCompare, UnknownPassNamesTheLineOrIsListedWhenAllowed) {
  const HandFrame f;
  try {
    f.compare("a,2\n# comment\nc,1\n");
    FAIL() << "expected a MeasurementError";
  } catch (const MeasurementError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "m.csv:3: field 'pass': 'c' is not a pass of the modelled frame (its passes: "
                  "a, b)"),
              std::string::npos)
        << e.what();
  }
  ValidateOptions allow;
  allow.allow_unknown_passes = true;
  const Validation v = f.compare("a,2\nb,3\nc,1\n", allow);
  EXPECT_EQ(v.not_modelled, std::vector<std::string>{"c"});
  ASSERT_EQ(v.rows.size(), 3u);
  EXPECT_FALSE(v.rows[2].model.has_value());
  EXPECT_FALSE(v.frame.compared());  // the sum would hold work the model does not have
  EXPECT_NE(format_validation(v).find("c (line 3)"), std::string::npos);
}

TEST(ValidateCompare, DramWaitIsARowWhenTheFrameIsBandwidthBound) {
  HandFrame f;
  f.timing.dram_wait_ms = 1.0;
  f.timing.frame_ms = 6.0;
  f.rows.push_back({1.0, 0.0, 2.0});
  const Validation v = f.compare("a,2\nb,3\n");
  ASSERT_EQ(v.rows.size(), 3u);
  EXPECT_EQ(v.rows[2].name, "dram_wait");
  EXPECT_EQ(v.not_measured, std::vector<std::string>{"dram_wait"});
  // Every pass is measured: the frame is their sum (a device does not report dram_wait).
  EXPECT_DOUBLE_EQ(*v.frame.measured_ms, 5.0);
  EXPECT_DOUBLE_EQ(v.frame.error_ms(), -1.0);
}

TEST(ValidateCompare, ADifferenceThatRoundsToZeroPrintsPlusZero) {
  const HandFrame f;
  const std::string table = format_validation(f.compare("a,1.9999\nb,3.0001\n"));
  EXPECT_EQ(table.find(" -0.000"), std::string::npos) << table;
  EXPECT_EQ(table.find(" -0.0 "), std::string::npos) << table;
  EXPECT_NE(table.find("+0.000"), std::string::npos) << table;
}

// The shipped example is a valid measurements file (its numbers are the model's own output).
TEST(ValidateParse, TheShippedExampleParses) {
  const Measurements m = read_measurements(std::string(test_paths::kDataDir) +
                                           "/measurements/example-ipad4-model-output.csv");
  EXPECT_EQ(m.passes.size(), 5u);
  EXPECT_TRUE(m.frame.has_value());
}

TEST(ValidateCompare, ZeroModelTimeHasNoPercentage) {
  HandFrame f;
  f.timing.schedule[0].exposed_ms = 0.0;
  f.rows[0] = {0.0, 0.0, 0.1};
  const Validation v = f.compare("a,0.05\n");
  EXPECT_FALSE(v.rows[0].error_percent().has_value());
  EXPECT_TRUE(v.rows[0].inside());
  EXPECT_NE(format_validation(v).find("n/a"), std::string::npos);
}

TEST(ValidateRanges, RowRangesHoldTheBaseAndMatchTheFrameRangeForOnePass) {
  // The shipped profile: its ranges hold its values (300 MHz in [280, 300]).
  const gpu_model::DeviceProfile profile =
      gpu_model::load_device_profile("ipad4", gpu_model::testing::kDataDir);
  sim::PassCounters alu = gpu_model::testing::make_pass(4, 4, 4);
  const std::uint32_t draw = gpu_model::testing::add_draw(alu, 200);
  for (std::size_t t = 0; t < alu.tiles.size(); ++t) {
    gpu_model::testing::shade(alu, t, draw, 1024);
  }
  gpu_model::testing::sum_tiles(alu);
  alu.name = "alu";

  const std::vector<ModelledMs> one = row_ms_ranges({alu}, profile);
  const gpu_model::FrameMsRange frame = gpu_model::frame_ms_range({alu}, profile);
  const gpu_model::FrameTiming timing = gpu_model::estimate_frame({alu}, profile);
  ASSERT_EQ(one.size(), 1u);
  ASSERT_EQ(timing.dram_wait_ms, 0.0);
  // One pass is the whole frame: its range is the frame's.
  EXPECT_DOUBLE_EQ(one[0].base, timing.schedule[0].exposed_ms);
  EXPECT_DOUBLE_EQ(one[0].low, frame.low);
  EXPECT_DOUBLE_EQ(one[0].high, frame.high);
  // 200 vector ops x 1024 fragments x 4 tiles per core / 8 pipes = 102400 cycles of ALU per
  // core; at the slow corner (vector ops at 2 cycles, 280 MHz) at least twice that at 280 MHz.
  EXPECT_GE(one[0].high, 2.0 * 102400.0 / 280e3);
  EXPECT_LT(one[0].base, 2.0 * 102400.0 / 280e3);
  EXPECT_LT(one[0].low, one[0].base);

  sim::PassCounters second = alu;
  second.name = "second";
  const std::vector<ModelledMs> two = row_ms_ranges({alu, second}, profile);
  const gpu_model::FrameTiming both = gpu_model::estimate_frame({alu, second}, profile);
  ASSERT_EQ(two.size(), 2u);
  for (std::size_t i = 0; i < two.size(); ++i) {
    EXPECT_DOUBLE_EQ(two[i].base, both.schedule[i].exposed_ms);
    EXPECT_LE(two[i].low, two[i].base);
    EXPECT_GE(two[i].high, two[i].base);
    EXPECT_LT(two[i].low, two[i].high);
  }
}

}  // namespace
}  // namespace skinsim::driver
