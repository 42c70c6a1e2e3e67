// Budgets on real frames of the built-in head (small, so the test is quick): determinism
// across thread counts, a deliberately heavier skin shader failing the budget with a message
// that names the pass and its ALU bottleneck, and bad devices and passes as bad input.
#include <gtest/gtest.h>

#include "budget/budget_file.h"
#include "budget/error.h"
#include "budget/evaluate.h"
#include "budget/run_budget.h"
#include "driver/frame/frame_job.h"
#include "gpu_model/frame_cost.h"
#include "gpu_model/profile_loader.h"
#include "tests/test_paths.h"

namespace skinsim::budget {
namespace {

const char* kBudgets = R"(
[[budget]]
name = "small"
device = "ipad4"
resolution = "320x240"
[budget.scene]
head_triangles = 8000
texture_size = 128
[budget.limits]
"skin.ms" = "<= baseline * 1.05"
"frame.ms" = "<= baseline * 1.05"
)";

class FrameBudget : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    file_ = new BudgetFile(parse_budget_file(kBudgets, "small.toml"));
    const Budget& b = file_->budgets.at(0);
    device_ = new gpu_model::DeviceProfile(gpu_model::load_device_profile("ipad4", kDataDir));
    scene_ = new scene::Scene(driver::load_scene(b.scene, 320.0f / 240.0f));
    gpu_scene_ = new pipeline::GpuScene(*scene_);
    frame_ = new driver::FrameResult(
        driver::run_frame(*gpu_scene_, driver::resolve_config(b.config, *device_), *device_, 1));
  }
  static void TearDownTestSuite() {
    delete frame_;
    delete gpu_scene_;
    delete scene_;
    delete device_;
    delete file_;
  }
  static inline const char* const kDataDir = test_paths::kDataDir;
  static inline BudgetFile* file_ = nullptr;
  static inline gpu_model::DeviceProfile* device_ = nullptr;
  static inline scene::Scene* scene_ = nullptr;
  static inline pipeline::GpuScene* gpu_scene_ = nullptr;
  static inline driver::FrameResult* frame_ = nullptr;
};

TEST_F(FrameBudget, MeasurementIsIdenticalForAnyThreadCount) {
  const Budget& b = file_->budgets.at(0);
  const BudgetRun one = run_budget("small.toml", b, kDataDir, 1, false);
  const BudgetRun three = run_budget("small.toml", b, kDataDir, 3, false);
  EXPECT_EQ(one.measurement.metrics, three.measurement.metrics);
  EXPECT_EQ(one.measurement.metrics, measure_frame(*frame_).metrics);
  EXPECT_EQ(one.device, "ipad4");
  EXPECT_EQ(one.device_hash, three.device_hash);
  // The measurement has every pass of the frame and the frame totals.
  for (const std::string pass : {"irradiance", "blur_h", "blur_v", "skin", "frame"}) {
    EXPECT_TRUE(one.measurement.metrics.count(pass + ".ms")) << pass;
  }
  EXPECT_GT(one.measurement.metrics.at("skin.alu_ops"), 0.0);
}

// The limits are "<= baseline * 1.05": the same frame against a baseline it is 4% above
// passes both, and against one it is 6% above fails both.
TEST_F(FrameBudget, AFrameWithinItsToleranceOfTheBaselinePasses) {
  const Measurement m = measure_frame(*frame_);
  const auto baseline_below = [&](double factor) {
    BaselineEntry base{"ipad4", "h", "", m.metrics};
    for (auto& [metric, value] : base.metrics) value /= factor;
    return base;
  };
  const BaselineEntry four = baseline_below(1.04), six = baseline_below(1.06);
  const auto within = evaluate_budget("small.toml", file_->budgets.at(0), m, &four);
  const auto beyond = evaluate_budget("small.toml", file_->budgets.at(0), m, &six);
  ASSERT_EQ(within.size(), 2u);
  ASSERT_EQ(beyond.size(), 2u);
  for (std::size_t i = 0; i < within.size(); ++i) {
    EXPECT_TRUE(within[i].passed) << within[i].limit.metric << ": " << within[i].message;
    EXPECT_FALSE(beyond[i].passed) << beyond[i].limit.metric;
  }
}

TEST_F(FrameBudget, HeavierSkinShaderFailsTheBudget) {
  const Measurement before = measure_frame(*frame_);
  const BaselineEntry base{"ipad4", "h", "", before.metrics};
  // A test-only heavier skin shader: twice the vector ALU ops per fragment, as if the shader
  // had grown, re-timed by the cost model.
  driver::FrameResult heavier = *frame_;
  bool found = false;
  for (sim::PassCounters& pass : heavier.output.passes) {
    for (sim::DrawCounters& draw : pass.draws) {
      if (draw.fragment_program == "skin_fs") {
        draw.fragment_profile.vector_ops *= 2;
        found = true;
      }
    }
  }
  ASSERT_TRUE(found) << "no draw ran skin_fs";
  heavier.timing = gpu_model::estimate_frame(heavier.output.passes, *device_);
  const Measurement after = measure_frame(heavier);
  const auto results = evaluate_budget("small.toml", file_->budgets.at(0), after, &base);
  ASSERT_EQ(results.size(), 2u);
  const LimitResult& skin = results[0];
  EXPECT_FALSE(skin.passed);
  EXPECT_NE(skin.message.find("skin.ms rose from"), std::string::npos) << skin.message;
  EXPECT_NE(skin.message.find("tolerance +5%"), std::string::npos) << skin.message;
  EXPECT_NE(skin.message.find("the skin pass is alu-bound"), std::string::npos) << skin.message;
  EXPECT_NE(skin.message.find("ALU ops"), std::string::npos) << skin.message;
  EXPECT_NE(skin.message.find("fragments shaded"), std::string::npos) << skin.message;
  const LimitResult& frame = results[1];
  EXPECT_FALSE(frame.passed);
  EXPECT_NE(frame.message.find("most of the change is the skin pass"), std::string::npos)
      << frame.message;
}

// An energy limit: the heavier shader does more ALU lane ops, so the skin pass's energy
// rises past "<= baseline * 1.05"; the frame's energy is the sum of its passes'.
TEST_F(FrameBudget, HeavierSkinShaderFailsAnEnergyLimit) {
  const Measurement before = measure_frame(*frame_);
  double passes_mj = 0.0;
  for (const std::string& pass : before.passes) passes_mj += before.metrics.at(pass + ".energy_mj");
  EXPECT_NEAR(passes_mj, before.metrics.at("frame.energy_mj"), 1e-9 * passes_mj);
  const BudgetFile energy = parse_budget_file(R"(
[[budget]]
name = "energy"
device = "ipad4"
[budget.limits]
"skin.energy_mj" = "<= baseline * 1.05"
)",
                                              "energy.toml");
  const BaselineEntry base{"ipad4", "h", "", before.metrics};
  driver::FrameResult heavier = *frame_;
  for (sim::PassCounters& pass : heavier.output.passes) {
    for (sim::DrawCounters& draw : pass.draws) {
      if (draw.fragment_program == "skin_fs") draw.fragment_profile.vector_ops *= 2;
    }
  }
  heavier.timing = gpu_model::estimate_frame(heavier.output.passes, *device_);
  const auto same = evaluate_budget("energy.toml", energy.budgets.at(0), before, &base);
  const auto grown =
      evaluate_budget("energy.toml", energy.budgets.at(0), measure_frame(heavier), &base);
  ASSERT_EQ(same.size(), 1u);
  ASSERT_EQ(grown.size(), 1u);
  EXPECT_TRUE(same[0].passed) << same[0].message;
  EXPECT_FALSE(grown[0].passed);
  EXPECT_NE(grown[0].message.find("skin.energy_mj rose from"), std::string::npos)
      << grown[0].message;
  EXPECT_NE(grown[0].message.find(" mJ"), std::string::npos) << grown[0].message;
}

TEST_F(FrameBudget, UnknownPassInARealFrameIsBadInput) {
  const BudgetFile f = parse_budget_file(R"(
[[budget]]
name = "typo"
device = "ipad4"
resolution = "320x240"
[budget.scene]
head_triangles = 8000
texture_size = 128
[budget.limits]
"skn.ms" = "<= 5"
)",
                                         "typo.toml");
  try {
    evaluate_budget("typo.toml", f.budgets[0], measure_frame(*frame_), nullptr);
    FAIL();
  } catch (const BudgetError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("typo.toml:10: budget 'typo', limit 'skn.ms'"), std::string::npos) << what;
    EXPECT_NE(what.find("irradiance, blur_h, blur_v, skin"), std::string::npos) << what;
  }
}

TEST_F(FrameBudget, UnknownDeviceIsBadInputNamingTheBudget) {
  Budget b = file_->budgets.at(0);
  b.device = "ipad9";
  try {
    run_budget("small.toml", b, kDataDir, 1, false);
    FAIL();
  } catch (const BudgetError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("small.toml:2: budget 'small', device 'ipad9'"), std::string::npos) << what;
  }
}

TEST_F(FrameBudget, MissingSceneFileIsBadInputNamingTheBudget) {
  Budget b = file_->budgets.at(0);
  b.scene.path = "/nonexistent/head.glb";
  try {
    run_budget("small.toml", b, kDataDir, 1, false);
    FAIL();
  } catch (const BudgetError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("small.toml:2: budget 'small', scene"), std::string::npos) << what;
    EXPECT_NE(what.find("/nonexistent/head.glb"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace skinsim::budget
