// report.html: links resolve, strings are escaped, the recommendation is the knee.
#include "reports/html_report.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "io/read_file.h"
#include "reports/display_check.h"
#include "reports/error.h"
#include "reports/knob_verdicts.h"
#include "reports/pareto.h"
#include "reports/recommendation.h"
#include "tests/reports/synthetic_sweep.h"
#include "tests/reports/test_output_dir.h"

namespace skinsim::reports {
namespace {

namespace fs = std::filesystem;
using testing::fresh_output_dir;
using testing::synthetic_sweep;

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The frame and error images the sweep would have written (tiny placeholder files).
void touch_images(const results::SweepTable& sweep, const std::string& dir) {
  for (const results::ConfigResult& r : sweep.rows) {
    for (const std::string& rel : {r.frame_image, r.error_image}) {
      fs::create_directories((fs::path(dir) / rel).parent_path());
      std::ofstream(fs::path(dir) / rel) << "image";
    }
  }
}

ReportOptions no_charts() {
  ReportOptions o;
  o.draw_charts = false;
  return o;
}

TEST(HtmlReport, EscapesEveryString) {
  EXPECT_EQ(escape_markup("<a href=\"x\">&'</a>"),
            "&lt;a href=&quot;x&quot;&gt;&amp;&#39;&lt;/a&gt;");
  results::SweepTable sweep = synthetic_sweep();
  sweep.device = "<script>alert('device')</script>";
  sweep.rows[0].label = "LUT <b>\"big\"</b> & co";
  sweep.rows[0].knobs["technique"] = "a<b";
  sweep.assumptions.push_back("clock < 300 MHz & \"maybe\"");
  const std::string dir = fresh_output_dir();
  const std::string html = read_text(write_report(sweep, dir, no_charts()));
  EXPECT_EQ(html.find("<script>"), std::string::npos);
  EXPECT_EQ(html.find("<b>\"big\""), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(&#39;device&#39;)&lt;/script&gt;"), std::string::npos);
  EXPECT_NE(html.find("LUT &lt;b&gt;&quot;big&quot;&lt;/b&gt; &amp; co"), std::string::npos);
  EXPECT_NE(html.find("clock &lt; 300 MHz &amp; &quot;maybe&quot;"), std::string::npos);
}

TEST(HtmlReport, LinksResolveWithoutCharts) {
  const results::SweepTable sweep = synthetic_sweep();
  const std::string dir = fresh_output_dir();
  touch_images(sweep, dir);
  write_report(sweep, dir, no_charts());
  EXPECT_TRUE(missing_report_links(dir).empty());
  EXPECT_TRUE(fs::exists(dir + "/results.json"));
  EXPECT_TRUE(fs::exists(dir + "/results.csv"));
  EXPECT_FALSE(fs::exists(dir + "/pass_times.png"));
}

TEST(HtmlReport, ShowsThumbnailsWhereTheyExistAndLinksTheFullImages) {
  const results::SweepTable sweep = synthetic_sweep();
  const std::string dir = fresh_output_dir();
  touch_images(sweep, dir);
  const std::string small = thumbnail_path(sweep.rows[0].frame_image);
  fs::create_directories((fs::path(dir) / small).parent_path());
  std::ofstream(fs::path(dir) / small) << "thumb";
  const std::string html = read_text(write_report(sweep, dir, no_charts()));
  EXPECT_NE(html.find("<a href=\"" + url_encode_path(sweep.rows[0].frame_image) + "\"><img src=\"" +
                      url_encode_path(small) + "\""),
            std::string::npos)
      << html;
  // No small copy of row 1's frame: the page shows the full-size one.
  EXPECT_NE(html.find("<img src=\"" + url_encode_path(sweep.rows[1].frame_image) + "\""),
            std::string::npos);
  EXPECT_TRUE(missing_report_links(dir).empty());
}

// The sweep writes its thumbnails beside the charts: the page, assembled after that work has
// finished, shows them; and the work's failure is the report's.
TEST(HtmlReport, WorkAlongsideTheChartsEndsBeforeThePage) {
  const results::SweepTable sweep = synthetic_sweep();
  const std::string dir = fresh_output_dir();
  touch_images(sweep, dir);
  const std::string small = thumbnail_path(sweep.rows[0].frame_image);
  ReportOptions options = no_charts();
  options.alongside_charts = [&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // later than the page would be
    fs::create_directories((fs::path(dir) / small).parent_path());
    std::ofstream(fs::path(dir) / small) << "thumb";
  };
  const std::string html = read_text(write_report(sweep, dir, options));
  EXPECT_NE(html.find("<img src=\"" + url_encode_path(small) + "\""), std::string::npos) << html;

  options.alongside_charts = [] { throw ReportError("thumbnail failed"); };
  EXPECT_THROW(write_report(sweep, fresh_output_dir(), options), ReportError);
}

TEST(HtmlReport, DrawsATimelinePerConfigurationWithTheRecommendedOneOpen) {
  const results::SweepTable sweep = synthetic_sweep();
  const std::string html = read_text(write_report(sweep, fresh_output_dir(), no_charts()));
  std::size_t timelines = 0;
  for (std::size_t at = html.find("<svg class=\"timeline\""); at != std::string::npos;
       at = html.find("<svg class=\"timeline\"", at + 1)) {
    ++timelines;
  }
  EXPECT_EQ(timelines, sweep.rows.size());
  EXPECT_NE(html.find("<details open><summary>"), std::string::npos);
}

TEST(HtmlReport, MissingImagesAreReported) {
  const results::SweepTable sweep = synthetic_sweep();
  const std::string dir = fresh_output_dir();
  touch_images(sweep, dir);
  fs::remove(fs::path(dir) / sweep.rows[3].error_image);
  write_report(sweep, dir, no_charts());
  EXPECT_EQ(missing_report_links(dir), std::vector<std::string>{sweep.rows[3].error_image});
}

TEST(HtmlReport, LinkCheckDecodesFileNames) {
  results::SweepTable sweep = synthetic_sweep();
  sweep.rows[0].frame_image = "frames/odd name & more.png";
  const std::string dir = fresh_output_dir();
  touch_images(sweep, dir);
  const std::string html = read_text(write_report(sweep, dir, no_charts()));
  EXPECT_NE(html.find("frames/odd%20name%20%26%20more.png"), std::string::npos);
  EXPECT_TRUE(missing_report_links(dir).empty());
  fs::remove(fs::path(dir) / sweep.rows[0].frame_image);
  EXPECT_EQ(missing_report_links(dir), std::vector<std::string>{"frames/odd name & more.png"});
}

TEST(HtmlReport, StatesTheRecommendationWithItsRangeAndRule) {
  const results::SweepTable sweep = synthetic_sweep();
  const std::vector<Recommendation> recommendations = recommend(sweep, "flip_skin");
  ASSERT_EQ(recommendations.size(), 1u);
  ASSERT_TRUE(recommendations[0].chosen);
  const results::ConfigResult& chosen = sweep.rows[*recommendations[0].chosen];
  const std::string html = read_text(write_report(sweep, fresh_output_dir(), no_charts()));
  const std::size_t section = html.find("<h2>Recommendation</h2>");
  ASSERT_NE(section, std::string::npos);
  const std::size_t next = html.find("<h2>", section + 1);
  const std::string text = html.substr(section, next - section);
  EXPECT_NE(text.find(escape_markup(recommendations[0].verdict)), std::string::npos) << text;
  EXPECT_NE(text.find(fmt::format("{:.2f} to {:.2f}", chosen.frame_ms_low, chosen.frame_ms_high)),
            std::string::npos)
      << text;
  EXPECT_NE(text.find(fmt::format("{:.3f} mJ ({:.3f} to {:.3f})", chosen.energy_mj,
                                  chosen.energy_mj_low, chosen.energy_mj_high)),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("How it is chosen"), std::string::npos);
}

// The text of the <h2> section that starts with `heading`, up to the next <h2>.
std::string section_of(const std::string& html, const std::string& heading) {
  const std::size_t at = html.find("<h2>" + heading);
  if (at == std::string::npos) return "";
  return html.substr(at, html.find("<h2>", at + 1) - at);
}

TEST(HtmlReport, StatesEachKnobsVerdictBeforeTheRecommendation) {
  const results::SweepTable sweep = synthetic_sweep();
  const std::string html = read_text(write_report(sweep, fresh_output_dir(), no_charts()));
  const std::string verdicts = section_of(html, "What each knob does");
  ASSERT_FALSE(verdicts.empty());
  EXPECT_LT(html.find("<h2>What each knob does"), html.find("<h2>Recommendation"));
  const std::vector<KnobVerdict> expected = knob_verdicts(sweep, "flip_skin");
  ASSERT_EQ(expected.size(), 2u);  // lut and scale
  for (const KnobVerdict& v : expected) {
    EXPECT_NE(verdicts.find(escape_markup(v.sentence)), std::string::npos) << v.sentence;
  }
}

TEST(HtmlReport, RecommendationNamesItsRangeAgainstTheBudgetAndTheRunnerUp) {
  results::SweepTable sweep = synthetic_sweep();
  const Recommendation r = recommend(sweep, "flip_skin").front();
  ASSERT_FALSE(r.range_note.empty());
  ASSERT_FALSE(r.runner_up_note.empty());
  const std::string text =
      section_of(read_text(write_report(sweep, fresh_output_dir(), no_charts())), "Recommendation");
  EXPECT_NE(text.find(escape_markup(r.range_note)), std::string::npos) << r.range_note;
  EXPECT_NE(text.find(escape_markup(r.runner_up_note)), std::string::npos) << r.runner_up_note;
}

TEST(HtmlReport, ExplainsTechniqueErrorAgainstKnobErrorBesideTheTable) {
  const results::SweepTable sweep = synthetic_sweep();
  const std::string text =
      section_of(read_text(write_report(sweep, fresh_output_dir(), no_charts())), "Configurations");
  EXPECT_NE(text.find("Technique error and knob error"), std::string::npos);
  const TechniqueError e = technique_errors(sweep, "flip_skin").front();
  EXPECT_NE(text.find(escape_markup(e.sentence)), std::string::npos) << e.sentence;
  // Every row visibly different from the reference: the page says what that column measures.
  results::SweepTable all_visible = sweep;
  for (results::ConfigResult& r : all_visible.rows) {
    r.reference_image = "refs/reference.png";
    r.visible_vs_reference = true;
  }
  const std::string explained = section_of(
      read_text(write_report(all_visible, fresh_output_dir(), no_charts())), "Configurations");
  EXPECT_NE(explained.find("16 of 16 configurations differ visibly from the reference (visible "
                           "vs reference): every technique&#39;s best does too"),
            std::string::npos)
      << explained.substr(0, 3000);
}

TEST(HtmlReport, TheSliderOffersEveryFrameOfTheGroupAndTheirDifference) {
  results::SweepTable sweep = synthetic_sweep();
  const Recommendation r = recommend(sweep, "flip_skin").front();
  results::ComparisonPanel panel;
  panel.chosen = sweep.rows[*r.chosen].id;
  panel.best = sweep.rows[*r.best].id;
  panel.reference_image = "refs/reference.png";
  panel.chosen_image = sweep.rows[*r.chosen].frame_image;
  panel.best_image = sweep.rows[*r.best].frame_image;
  panel.difference_gain = 8.0;
  panel.colour_bar = "compare/colour_bar.png";
  sweep.panels = {panel};
  const std::string text =
      section_of(read_text(write_report(sweep, fresh_output_dir(), no_charts())),
                 "What the recommendation looks like");
  const std::size_t left = text.find("<select class=\"left\">");
  ASSERT_NE(left, std::string::npos) << text;
  const std::string options = text.substr(left, text.find("</select>", left) - left);
  for (const results::ConfigResult& row : sweep.rows) {
    EXPECT_NE(options.find("value=\"" + row.frame_image + "\""), std::string::npos) << row.id;
  }
  EXPECT_NE(options.find("value=\"refs/reference.png\">reference<"), std::string::npos);
  EXPECT_NE(options.find("value=\"" + panel.chosen_image + "\" selected>recommended: "),
            std::string::npos)
      << options;
  EXPECT_NE(text.find("class=\"diff\" value=\"8\""), std::string::npos) << text;
}

TEST(HtmlReport, SaysSoWhenNothingFitsTheBudget) {
  results::SweepTable sweep = synthetic_sweep();
  sweep.budget_ms = 1.0;
  const std::string html = read_text(write_report(sweep, fresh_output_dir(), no_charts()));
  EXPECT_NE(html.find("no configuration fits the 1.0 ms budget"), std::string::npos);
}

TEST(HtmlReport, ComparesTechniquesWithTheirProgramsWhenThereAreSeveral) {
  results::SweepTable sweep = synthetic_sweep();
  const std::string single = read_text(write_report(sweep, fresh_output_dir(), no_charts()));
  EXPECT_EQ(single.find("Techniques compared"), std::string::npos);
  for (std::size_t i = 0; i < sweep.rows.size(); ++i) {
    results::ConfigResult& r = sweep.rows[i];
    r.knobs["technique"] = i % 2 ? "wrap" : "mobile";
    r.programs = {{"skin", i % 2 ? "wrap_fs" : "skin_fs", 2.5e6, 30, 18, 7, 4, 1},
                  {"skin", "background_fs", 1e5, 8, 1, 4, 1, 0}};
  }
  const std::string html = read_text(write_report(sweep, fresh_output_dir(), no_charts()));
  EXPECT_NE(html.find("Techniques compared"), std::string::npos);
  EXPECT_NE(html.find("skin_fs (skin): 30+18+7 ALU, 4+1 tex, 2.50 M frag"), std::string::npos);
  EXPECT_NE(html.find("wrap_fs (skin)"), std::string::npos);
  EXPECT_EQ(html.find("background_fs (skin)"), std::string::npos);
}

TEST(HtmlReport, AKnobARowDoesNotUseShowsAsADash) {
  results::SweepTable sweep = synthetic_sweep();
  sweep.rows[0].knobs.erase("scale");
  sweep.rows[0].label = "scale-free";
  const std::string html = read_text(write_report(sweep, fresh_output_dir(), no_charts()));
  const auto row = html.find("<td class=\"text\">scale-free</td>");
  ASSERT_NE(row, std::string::npos);
  const std::string cells = html.substr(row, html.find("</tr>", row) - row);
  EXPECT_NE(cells.find("<td class=\"text\">-</td>"), std::string::npos) << cells;
}

TEST(HtmlReport, SaysSoWhenNoRowHasTheMetric) {
  ReportOptions options = no_charts();
  options.quality_metric = "no_such_metric";
  const std::string html = read_text(write_report(synthetic_sweep(), fresh_output_dir(), options));
  EXPECT_NE(html.find("No configuration has the quality metric no_such_metric"), std::string::npos);
}

TEST(HtmlReport, MissingReportIsAnError) {
  EXPECT_THROW(missing_report_links(fresh_output_dir()), io::InputError);
}

TEST(HtmlReport, WithChartsAllLinksResolve) {
  std::string why;
  if (!charts_available(&why)) GTEST_SKIP() << why;
  const results::SweepTable sweep = synthetic_sweep();
  const std::string dir = fresh_output_dir();
  touch_images(sweep, dir);
  const std::string html = read_text(write_report(sweep, dir));
  EXPECT_TRUE(missing_report_links(dir).empty());
  for (const char* chart :
       {"tradeoff_by_lut.png", "tradeoff_by_scale.png", "energy_vs_quality.png", "pass_times.png",
        "tile_cost.png", "tile_bottleneck.png", "dram_by_cause.png"}) {
    EXPECT_TRUE(fs::exists(fs::path(dir) / chart)) << chart;
    EXPECT_NE(html.find(std::string("src=\"") + chart), std::string::npos) << chart;
  }
  EXPECT_NE(html.find("href=\"pass_times.svg\""), std::string::npos);
  // One technique in frame-time order would join unrelated configurations: not drawn.
  EXPECT_FALSE(fs::exists(fs::path(dir) / "tradeoff_by_technique.png"));
}

}  // namespace
}  // namespace skinsim::reports
