// One sentence per knob from hand-made result tables, one per wording branch: time effect or
// not (saves, costs, both), visible effect or not, one value, not varied alone, the technique
// knob, group knobs left out; technique error against knob error; results.json's findings.
#include "reports/knob_verdicts.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/read_file.h"
#include "reports/sweep_json.h"
#include "results/sweep_table.h"
#include "tests/scratch_dir.h"

namespace skinsim::reports {
namespace {

// A row of group "g" with `knobs`, `ms` and FLIP `flip` against the reference; its
// comparison with `finest` (FLIP `against`, `px` pixels above the threshold, visible at 30).
results::ConfigResult row(const std::string& id, std::map<std::string, std::string> knobs,
                          double ms, double flip, const std::string& finest, double px) {
  results::ConfigResult r;
  r.id = id;
  r.group = "g";
  r.knobs = std::move(knobs);
  r.frame_ms = ms;
  r.frame_ms_low = ms * 0.8;
  r.frame_ms_high = ms * 1.5;
  r.quality["flip_skin"] = flip;
  r.vs_finest = results::FrameComparison{finest, id == finest ? 0.0 : 0.02, 0.1, px, px >= 30.0};
  r.vs_best = r.vs_finest;
  return r;
}

results::SweepTable table(std::vector<results::ConfigResult> rows) {
  results::SweepTable t;
  t.budget_ms = 33.3;
  t.rows = std::move(rows);
  return t;
}

KnobVerdict verdict_for(const std::vector<KnobVerdict>& all, const std::string& knob,
                        const std::string& technique = "mobile") {
  for (const KnobVerdict& v : all) {
    if (v.knob == knob && v.technique == technique) return v;
  }
  throw std::runtime_error("no verdict for " + knob);
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A LUT x scale grid of "mobile" around fine = (scale 1, lut 64x256): the LUT costs nothing
// and shows, the scale saves time and does not show.
results::SweepTable lut_and_scale() {
  const auto k = [](const std::string& scale, const std::string& lut) {
    return std::map<std::string, std::string>{
        {"technique", "mobile"}, {"scale", scale}, {"lut", lut}, {"device", "ipad4"}};
  };
  return table({row("fine", k("1", "64x256"), 28.0, 0.050, "fine", 0),
                row("small_lut", k("1", "8x32"), 27.9, 0.060, "fine", 1234),
                row("half", k("0.5", "64x256"), 18.0, 0.051, "fine", 12),
                row("half_small_lut", k("0.5", "8x32"), 17.9, 0.061, "fine", 1500)});
}

TEST(KnobVerdicts, NoTimeEffectButVisible) {
  const std::vector<KnobVerdict> all = knob_verdicts(lut_and_scale(), "flip_skin");
  const KnobVerdict lut = verdict_for(all, "lut");
  EXPECT_EQ(lut.kind, KnobVerdict::Kind::measured);
  EXPECT_FALSE(lut.time_effect);  // 0.1 ms of 28: under 1%
  EXPECT_TRUE(lut.visible_effect);
  EXPECT_EQ(lut.around, "fine");
  EXPECT_TRUE(has(lut.sentence,
                  "lut (mobile): no time effect (27.90 to 28.00 ms over its 2 "
                  "values)"))
      << lut.sentence;
  EXPECT_TRUE(has(lut.sentence, "lut 8x32 on 1,234 px of skin")) << lut.sentence;
}

TEST(KnobVerdicts, SavesTimeAndInvisible) {
  const KnobVerdict scale = verdict_for(knob_verdicts(lut_and_scale(), "flip_skin"), "scale");
  EXPECT_TRUE(scale.time_effect);
  EXPECT_FALSE(scale.visible_effect);
  EXPECT_TRUE(has(scale.sentence, "scale 0.5 saves 10.00 ms against scale 1 (28.00 -> 18.00 ms)"))
      << scale.sentence;
  EXPECT_TRUE(has(scale.sentence, "no value looks different from scale 1 (at most 12 px above"))
      << scale.sentence;
}

TEST(KnobVerdicts, OnlyDearerValuesAndBothDirections) {
  const auto k = [](const std::string& taps) {
    return std::map<std::string, std::string>{{"technique", "mobile"}, {"shadow_taps", taps}};
  };
  // The finest is the middle value: one value is cheaper, one dearer.
  results::SweepTable t =
      table({row("t1", k("1"), 20.0, 0.07, "t4", 800), row("t4", k("4"), 25.3, 0.05, "t4", 0),
             row("t16", k("16"), 31.0, 0.0501, "t4", 5)});
  const KnobVerdict both = verdict_for(knob_verdicts(t, "flip_skin"), "shadow_taps");
  EXPECT_TRUE(has(both.sentence,
                  "shadow_taps 1 saves 5.30 ms and shadow_taps 16 costs 5.70 ms "
                  "more than shadow_taps 4 (20.00, 25.30, 31.00 ms)"))
      << both.sentence;
  EXPECT_TRUE(has(both.sentence, "shadow_taps 1 on 800 px of skin")) << both.sentence;
  // Without the cheaper value the finest is also the cheapest.
  t.rows.erase(t.rows.begin());
  const KnobVerdict dearer = verdict_for(knob_verdicts(t, "flip_skin"), "shadow_taps");
  EXPECT_TRUE(has(dearer.sentence,
                  "no value saves time against shadow_taps 4; shadow_taps 16 "
                  "costs 5.70 ms more (25.30 -> 31.00 ms)"))
      << dearer.sentence;
}

TEST(KnobVerdicts, AKnobWithOneValueForATechniqueIsNotMeasured) {
  const auto k = [](const std::string& technique, const std::string& lut) {
    return std::map<std::string, std::string>{{"technique", technique}, {"lut", lut}};
  };
  const results::SweepTable t =
      table({row("m1", k("mobile", "8x32"), 10.0, 0.06, "m2", 100),
             row("m2", k("mobile", "64x256"), 10.0, 0.05, "m2", 0),
             row("p1", k("preintegrated", "64x256"), 12.0, 0.04, "p1", 0)});
  const std::vector<KnobVerdict> all = knob_verdicts(t, "flip_skin");
  const KnobVerdict one = verdict_for(all, "lut", "preintegrated");
  EXPECT_EQ(one.kind, KnobVerdict::Kind::one_value);
  EXPECT_EQ(one.sentence,
            "lut (preintegrated): only 64x256 was swept, so its effect is not measured.");
}

TEST(KnobVerdicts, KnobsThatNeverVaryAloneAreSaidSo) {
  const auto k = [](const std::string& a, const std::string& b) {
    return std::map<std::string, std::string>{{"technique", "mobile"}, {"scale", a}, {"lut", b}};
  };
  const results::SweepTable t = table({row("x", k("1", "64x256"), 20.0, 0.05, "x", 0),
                                       row("y", k("0.5", "8x32"), 10.0, 0.08, "x", 900)});
  const KnobVerdict lut = verdict_for(knob_verdicts(t, "flip_skin"), "lut");
  EXPECT_EQ(lut.kind, KnobVerdict::Kind::not_isolated);
  EXPECT_TRUE(has(lut.sentence, "no configuration differs from x in this knob alone"))
      << lut.sentence;
}

TEST(KnobVerdicts, TheTechniqueIsJudgedOnEachTechniquesBestAgainstTheGroupsBest) {
  const auto k = [](const std::string& technique, const std::string& lut) {
    return std::map<std::string, std::string>{{"technique", technique}, {"lut", lut}};
  };
  results::SweepTable t = table({row("m", k("mobile", "64x256"), 8.08, 0.09, "m", 0),
                                 row("m_small", k("mobile", "8x32"), 8.0, 0.095, "m", 50),
                                 row("b", k("burley", "64x256"), 24.81, 0.03, "b", 0)});
  t.rows[0].vs_best = results::FrameComparison{"b", 0.05, 0.3, 14026, true};
  t.rows[1].vs_best = results::FrameComparison{"b", 0.06, 0.3, 15000, true};
  t.rows[2].vs_best = results::FrameComparison{"b", 0.0, 0.0, 0, false};
  const std::vector<KnobVerdict> all = knob_verdicts(t, "flip_skin");
  ASSERT_FALSE(all.empty());
  EXPECT_EQ(all[0].knob, "technique");  // first in its group
  EXPECT_TRUE(all[0].time_effect);
  EXPECT_TRUE(all[0].visible_effect);
  EXPECT_EQ(all[0].sentence,
            "technique (each at its best knobs): burley is the closest to the reference at "
            "24.81 ms; mobile 8.08 ms (saves 16.73 ms), visibly different on 14,026 px of skin.");
  // A technique whose rows do not use a knob gets no verdict for it.
  t.rows[2].knobs.erase("lut");
  for (const KnobVerdict& v : knob_verdicts(t, "flip_skin")) {
    EXPECT_FALSE(v.technique == "burley" && v.knob == "lut") << v.sentence;
  }
  // A technique that costs the same and looks the same: said so.
  t.rows[0].frame_ms = 24.8;
  t.rows[0].frame_ms_low = 20.0;
  t.rows[0].vs_best = results::FrameComparison{"b", 0.01, 0.05, 3, false};
  const KnobVerdict same = knob_verdicts(t, "flip_skin")[0];
  EXPECT_FALSE(same.time_effect);
  EXPECT_FALSE(same.visible_effect);
  EXPECT_TRUE(has(same.sentence, "mobile 24.80 ms (no time difference), looks the same"))
      << same.sentence;
}

TEST(KnobVerdicts, KnobsThatDefineTheGroupsAreNotJudged) {
  results::SweepTable t = lut_and_scale();
  std::vector<results::ConfigResult> other = t.rows;
  for (results::ConfigResult& r : other) {
    r.id += "_iphone";
    r.group = "iphone";
    r.knobs["device"] = "iphone5";
    r.vs_finest->against += "_iphone";
  }
  t.rows.insert(t.rows.end(), other.begin(), other.end());
  const std::vector<KnobVerdict> all = knob_verdicts(t, "flip_skin");
  EXPECT_EQ(all.size(), 4u);  // lut and scale, in each group
  for (const KnobVerdict& v : all) EXPECT_NE(v.knob, "device");
}

TEST(KnobVerdicts, VisibilityNotMeasuredWithoutComparisons) {
  results::SweepTable t = lut_and_scale();
  for (results::ConfigResult& r : t.rows) r.vs_finest.reset();
  const KnobVerdict lut = verdict_for(knob_verdicts(t, "flip_skin"), "lut");
  EXPECT_TRUE(has(lut.sentence, "its visible effect was not measured")) << lut.sentence;
}

TEST(TechniqueErrors, SplitTheErrorAgainstTheReferenceFromWhatTheKnobsAdd) {
  const std::vector<TechniqueError> errors = technique_errors(lut_and_scale(), "flip_skin");
  ASSERT_EQ(errors.size(), 1u);
  const TechniqueError& e = errors[0];
  EXPECT_EQ(e.finest, "fine");
  EXPECT_DOUBLE_EQ(e.technique_error, 0.050);
  EXPECT_EQ(e.visibly_worse, 2);  // small_lut and half_small_lut
  EXPECT_EQ(e.configurations, 4);
  EXPECT_TRUE(has(e.sentence,
                  "mobile: flip_skin 0.0500 against the reference at its best "
                  "knobs (fine), the technique error"))
      << e.sentence;
  EXPECT_TRUE(has(e.sentence, "2 of its 3 other configurations differ visibly")) << e.sentence;
  // A technique swept at one configuration has no knob error to state.
  results::SweepTable single = lut_and_scale();
  single.rows.resize(1);
  EXPECT_TRUE(
      has(technique_errors(single, "flip_skin")[0].sentence, "so the knob error is not measured"));
}

TEST(Findings, ResultsJsonKeepsThemAndReadingIgnoresThem) {
  const results::SweepTable t = lut_and_scale();
  EXPECT_EQ(unswept_knobs(t), (std::vector<std::string>{"device=ipad4", "technique=mobile"}));
  const std::string path =
      (skinsim::testing::scratch_root("skinsim_knob_verdicts") / "results.json").string();
  write_sweep_json(t, path);
  const nlohmann::json j = nlohmann::json::parse(io::read_regular_file(path, "results"));
  ASSERT_TRUE(j.contains("findings"));
  EXPECT_EQ(j["findings"]["metric"], "flip_skin");
  EXPECT_EQ(j["findings"]["recommendations"][0]["chosen"], "half");
  EXPECT_EQ(j["findings"]["knob_verdicts"].size(), 2u);
  EXPECT_EQ(j["findings"]["technique_errors"][0]["finest"], "fine");
  EXPECT_EQ(results::read_sweep_json(path).rows.size(), t.rows.size());
}

}  // namespace
}  // namespace skinsim::reports
