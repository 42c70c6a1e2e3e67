// The "Judged by truth" section of a sweep's report (driver/truth/truth_report.h) on a hand-made
// table: the noise floor, the recommendation under both judges, the flipped verdicts, and
// whether the truth can separate the configurations, with the samples it would need.
#include "driver/truth/truth_report.h"

#include <gtest/gtest.h>

#include <string>

namespace skinsim::driver {
namespace {

results::ConfigResult row(const std::string& id, double flip, double truth_flip, bool visible,
                          bool visible_by_truth) {
  results::ConfigResult r;
  r.id = id;
  r.group = "ipad4, 128x96";
  r.frame_image = "configs/" + id + ".png";
  r.reference_image = "reference.png";
  r.visible_vs_reference = visible;
  r.quality = {{"flip_skin", flip},
               {"truth_flip_skin", truth_flip},
               {"truth_visible_skin", visible_by_truth ? 1.0 : 0.0}};
  return r;
}

// One group judged by a 64-sample truth whose floor is FLIP `floor`.
nlohmann::json judged(double floor, bool same) {
  return nlohmann::json::array(
      {{{"group", "ipad4, 128x96"},
        {"image", "truth/g0.png"},
        {"truth",
         {{"source", "store"},
          {"store", "/cache/truths/truth_1.json"},
          {"key", {{"samples", 64}, {"seed", 1}, {"second_seed", 2}, {"blender", "Blender 3.4"}}}}},
        {"noise_floor",
         {{"measured", true}, {"skin", {{"psnr_db", 25.0}, {"ssim", 0.75}, {"flip", floor}}}}},
        {"recommended_by_reference", "a"},
        {"recommended_by_truth", same ? "a" : "b"},
        {"recommendation_same", same},
        {"verdict_by_truth", "b: the cheapest"},
        {"visibility_verdicts", 2},
        {"visibility_verdicts_changed",
         {{{"id", "b"}, {"visible_by_reference", true}, {"visible_by_truth", false}}}}}});
}

results::SweepTable table() {
  results::SweepTable t;
  t.rows = {row("a", 0.05, 0.110, false, false), row("b", 0.09, 0.115, true, false)};
  return t;
}

bool has(const std::string& html, const std::string& text) {
  return html.find(text) != std::string::npos;
}

TEST(TruthReport, SamplesToSeparateFallAsTheSquareOfTheFloor) {
  EXPECT_EQ(samples_to_separate(0.1, 0.05, 64), 256.0);  // half the floor: 4x the samples
  EXPECT_EQ(samples_to_separate(0.1, 0.1, 64), 64.0);
  EXPECT_FALSE(samples_to_separate(0.1, 0.0, 64));
}

TEST(TruthReport, SaysWhenTheTruthCannotSeparateTheConfigurations) {
  const std::string h = truth_report_section(table(), judged(0.095, false));
  EXPECT_TRUE(has(h, "<h2>Judged by truth</h2>"));
  EXPECT_TRUE(has(h, "sRGB transfer function, clamped to [0, 1], rounded to 8 bits"));
  EXPECT_TRUE(has(h, "FLIP 0.095"));  // the floor
  EXPECT_TRUE(has(h, "Recommendation: changed</b>: a under the reference, b under the truth"));
  EXPECT_TRUE(has(h, "1 of 2 &quot;visibly different&quot; verdicts stay")) << h;
  EXPECT_TRUE(has(h,
                  "<code>b</code>: visibly different from the reference, not visibly "
                  "different from the truth"));
  // Spread 0.005 against a floor of 0.095: (0.095 / 0.005)^2 x 64 = 23104 samples.
  EXPECT_TRUE(has(h, "this truth cannot separate the configurations")) << h;
  EXPECT_TRUE(has(h, "Its different recommendation above is within its noise."));
  EXPECT_TRUE(has(h, "about 23104 samples")) << h;
  EXPECT_TRUE(has(h, "--truth cached --truth-samples 23104"));
}

TEST(TruthReport, SaysWhenTheTruthSeparatesThem) {
  const std::string h = truth_report_section(table(), judged(0.004, true));
  EXPECT_TRUE(has(h, "Recommendation: the same</b> under the truth as under the reference: a"));
  EXPECT_TRUE(has(h, "this truth separates them"));
  EXPECT_FALSE(has(h, "cannot separate"));
  EXPECT_FALSE(has(h, "within its noise"));
  EXPECT_EQ(truth_report_images(judged(0.004, true)).at("ipad4, 128x96"), "truth/g0.png");
}

TEST(TruthReport, NothingWithoutATruth) {
  EXPECT_EQ(truth_report_section(table(), nullptr), "");
  EXPECT_TRUE(truth_report_images(nullptr).empty());
}

}  // namespace
}  // namespace skinsim::driver
