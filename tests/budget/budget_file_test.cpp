// Budget files: a complete file reads into budgets; every kind of bad input is rejected
// with the file and line in the message.
#include "budget/budget_file.h"

#include <gtest/gtest.h>

#include "budget/error.h"
#include "util/user_error.h"

namespace skinsim::budget {
namespace {

const char* kValid = R"(baseline = "base/b.json"

[[budget]]
name = "ipad"
device = "ipad4"
resolution = "640x480"
target_fps = 30

[budget.scene]
path = "heads/lee.glb"
head_triangles = 20000
texture_size = 256
skin_materials = ["all"]
units_per_mm = 0.04

[budget.pipeline]
scale = 0.25
lut = "64x256"
blur_iterations = 2

[budget.limits]
"skin.ms" = "<= baseline * 1.05"
"frame.ms" = ["<= 16.6", "<= baseline * 1.1"]
"quality.ssim_skin" = ">= 0.99"

[[budget]]
name = "iphone"
device = "profiles/my_phone.toml"
[budget.limits]
"frame.dram_bytes" = "<= 3e7"
)";

TEST(BudgetFile, ReadsEveryField) {
  const BudgetFile f = parse_budget_file(kValid, "ci/budgets.toml");
  EXPECT_EQ(f.baseline_path, std::filesystem::path("ci/base/b.json"));
  ASSERT_EQ(f.budgets.size(), 2u);
  const Budget& b = f.budgets[0];
  EXPECT_EQ(b.name, "ipad");
  EXPECT_EQ(b.line, 3);
  EXPECT_EQ(b.device, "ipad4");
  EXPECT_EQ(b.config.width, 640);
  EXPECT_EQ(b.config.height, 480);
  EXPECT_FLOAT_EQ(b.config.mobile.scale, 0.25f);
  EXPECT_EQ(b.config.lut_width, 64);
  EXPECT_EQ(b.config.mobile.blur_iterations, 2);
  EXPECT_DOUBLE_EQ(b.target_fps, 30.0);
  EXPECT_EQ(b.scene.path, "ci/heads/lee.glb");
  EXPECT_EQ(b.scene.head_triangles, 20000);
  EXPECT_EQ(b.scene.texture_size, 256);
  EXPECT_EQ(b.scene.skin_materials, std::vector<std::string>{"all"});
  EXPECT_FLOAT_EQ(b.scene.units_per_mm, 0.04f);
  // In file order, the list expanded in place.
  ASSERT_EQ(b.limits.size(), 4u);
  EXPECT_EQ(b.limits[0].metric, "skin.ms");
  EXPECT_EQ(b.limits[0].line, 22);
  EXPECT_EQ(b.limits[1].metric, "frame.ms");
  EXPECT_EQ(b.limits[2].metric, "frame.ms");
  EXPECT_TRUE(b.limits[2].uses_baseline());
  EXPECT_EQ(b.limits[3].metric, "quality.ssim_skin");
  EXPECT_TRUE(b.needs_quality());
  EXPECT_TRUE(b.needs_baseline());
  const Budget& phone = f.budgets[1];
  EXPECT_EQ(phone.device, "ci/profiles/my_phone.toml");
  EXPECT_TRUE(phone.scene.builtin());
  EXPECT_FALSE(phone.needs_quality());
  EXPECT_FALSE(phone.needs_baseline());
}

TEST(BudgetFile, DefaultBaselineSitsBesideTheFile) {
  const BudgetFile f = parse_budget_file(
      "[[budget]]\nname='a'\ndevice='ipad4'\n[budget.limits]\n'frame.ms' = '<= 20'\n",
      "ci/perf.toml");
  EXPECT_EQ(f.baseline_path, std::filesystem::path("ci/perf.baseline.json"));
}

struct BadCase {
  std::string text;
  const char* expected;  // substring of the message after "bad.toml:<line>:"
  int line;
};

// Appends rather than concatenating temporaries: GCC 12 warns falsely (-Wrestrict) on
// `literal + string`.
std::string budget_with(const std::string& body, int copies = 1) {
  std::string text;
  for (int i = 0; i < copies; ++i)
    text.append("[[budget]]\nname = 'b'\ndevice = 'ipad4'\n").append(body);
  return text;
}

TEST(BudgetFile, BadInputNamesFileLineAndField) {
  const std::vector<BadCase> cases = {
      {"[[budget]\nname='x'", "malformed TOML", 1},
      {"title = 'x'\n", "unknown key 'title'", 1},
      {"# nothing\n", "no budgets", 1},
      {"budget = 3\n", "no budgets", 1},
      {"[[budget]]\ndevice='ipad4'\n[budget.limits]\n'frame.ms'='<= 1'\n", "has no name", 1},
      {"[[budget]]\nname='b'\n[budget.limits]\n'frame.ms'='<= 1'\n", "has no device", 1},
      {budget_with("colour = 'red'\n[budget.limits]\n'frame.ms'='<= 1'\n"), "unknown key 'colour'",
       4},
      {budget_with("resolution = 'big'\n[budget.limits]\n'frame.ms'='<= 1'\n"), "resolution", 4},
      {budget_with("target_fps = -1\n[budget.limits]\n'frame.ms'='<= 1'\n"), "target_fps", 4},
      {budget_with("[budget.pipeline]\nwarp = 2\n[budget.limits]\n'frame.ms'='<= 1'\n"),
       "unknown pipeline knob 'warp'", 5},
      {budget_with("[budget.pipeline]\nscale = 7.5\n[budget.limits]\n'frame.ms'='<= 1'\n"),
       "pipeline: scale must be in (0, 1]", 4},
      {budget_with("[budget.pipeline]\nscale = true\n[budget.limits]\n'frame.ms'='<= 1'\n"),
       "string or a number", 5},
      {budget_with("[budget.scene]\nhead_triangles = 5\n[budget.limits]\n'frame.ms'='<= 1'\n"),
       "head_triangles", 5},
      {budget_with("[budget.scene]\nfile = 'a.glb'\n[budget.limits]\n'frame.ms'='<= 1'\n"),
       "unknown key 'file'", 5},
      {budget_with(""), "needs a [budget.limits] table", 1},
      {budget_with("[budget.limits]\n"), "has no limits", 1},
      {budget_with("[budget.limits]\n'skin.speed' = '<= 1'\n"),
       "limit 'skin.speed': no such metric", 5},
      {budget_with("[budget.limits]\n'quality.psnr' = '>= 30'\n"), "no such metric", 5},
      {budget_with("[budget.limits]\n'frame.ms' = 16\n"), "must be a string", 5},
      {budget_with("[budget.limits]\n'frame.ms' = []\n"), "empty list", 5},
      {budget_with("[budget.limits]\n'frame.ms' = '< 16'\n"), "must start with <= or >=", 5},
      {budget_with("[budget.limits]\n'frame.ms'='<= 1'\n", 2), "duplicate budget name 'b'", 6},
  };
  for (const BadCase& c : cases) {
    try {
      parse_budget_file(c.text, "bad.toml");
      ADD_FAILURE() << "accepted:\n" << c.text;
    } catch (const BudgetError& e) {
      const std::string what = e.what();
      const std::string where = "bad.toml:" + std::to_string(c.line) + ":";
      EXPECT_EQ(what.rfind(where, 0), 0u) << "expected " << where << " in: " << what;
      EXPECT_NE(what.find(c.expected), std::string::npos)
          << "expected '" << c.expected << "' in: " << what;
    }
  }
}

TEST(BudgetFile, MissingFileIsNamed) {
  try {
    load_budget_file("/nonexistent/budgets.toml");
    FAIL();
  } catch (const UserError& e) {  // io::InputError, from the shared input reader
    EXPECT_NE(std::string(e.what()).find("/nonexistent/budgets.toml"), std::string::npos);
  }
}

}  // namespace
}  // namespace skinsim::budget
