// Baseline files round-trip and report their provenance; JUnit XML escapes and counts.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "budget/baseline_file.h"
#include "budget/device_fingerprint.h"
#include "budget/error.h"
#include "budget/junit.h"
#include "util/text.h"

namespace skinsim::budget {
namespace {

std::filesystem::path temp_path(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "skinsim_budget_test";
  std::filesystem::create_directories(dir);
  return dir / name;
}

TEST(Baseline, RoundTripsExactlyIncludingInfinity) {
  Baseline b;
  b.skinsim_version = "9.9.9";
  b.budgets["a"] = {"ipad4",
                    "fnv1a64:0123",
                    "fnv1a64:4567",
                    {{"frame.ms", 5.356606482303355}, {"quality.psnr_skin", HUGE_VAL}}};
  const auto path = temp_path("roundtrip.json");
  save_baseline(b, path);
  const Baseline back = load_baseline(path);
  EXPECT_EQ(back.skinsim_version, "9.9.9");
  EXPECT_EQ(back.budgets.at("a").device_hash, "fnv1a64:0123");
  EXPECT_EQ(back.budgets.at("a").definition_hash, "fnv1a64:4567");
  EXPECT_EQ(back.budgets.at("a").metrics.at("frame.ms"), 5.356606482303355);
  EXPECT_TRUE(std::isinf(back.budgets.at("a").metrics.at("quality.psnr_skin")));
}

TEST(Baseline, MalformedOrMissingFilesAreNamed) {
  const auto path = temp_path("bad.json");
  for (const char* text : {"{", R"({"format": "other/1"})", R"({"format": 3})"}) {
    std::ofstream(path) << text;
    try {
      load_baseline(path);
      ADD_FAILURE() << text;
    } catch (const BudgetError& e) {
      EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
  }
  std::ofstream(path) << R"({"format": "skinsim-budget-baseline/1", "skinsim_version": "1",
      "budgets": {"a": {"device": "x", "device_hash": "h", "metrics": {"frame.ms": "fast"}}}})";
  try {
    load_baseline(path);
    ADD_FAILURE() << "accepted a non-numeric metric";
  } catch (const BudgetError& e) {
    EXPECT_NE(std::string(e.what()).find("budgets.a.metrics.frame.ms"), std::string::npos);
  }
  EXPECT_THROW(load_baseline(temp_path("missing.json")), BudgetError);
}

TEST(Baseline, WarnsWhenToolOrDeviceProfileDiffer) {
  Baseline b;
  b.skinsim_version = "0.0.1";
  b.budgets["a"] = {"ipad4", fingerprint("profile v1"), fingerprint("definition v1"), {}};
  EXPECT_FALSE(version_warning(b, "0.0.1"));
  ASSERT_TRUE(version_warning(b, "0.2.0"));
  EXPECT_NE(version_warning(b, "0.2.0")->find("skinsim 0.0.1"), std::string::npos);
  EXPECT_FALSE(device_warning(b, "a", "ipad4", fingerprint("profile v1")));
  EXPECT_NE(device_warning(b, "a", "ipad4", fingerprint("profile v2"))->find("changed"),
            std::string::npos);
  EXPECT_NE(device_warning(b, "a", "iphone5", fingerprint("profile v1"))->find("'iphone5'"),
            std::string::npos);
  EXPECT_FALSE(device_warning(b, "other", "ipad4", "x"));
  EXPECT_FALSE(definition_warning(b, "a", fingerprint("definition v1"), "f.toml"));
  const auto edited = definition_warning(b, "a", fingerprint("definition v2"), "f.toml");
  ASSERT_TRUE(edited);
  EXPECT_NE(edited->find("skinsim baseline f.toml --update"), std::string::npos) << *edited;
  EXPECT_FALSE(definition_warning(b, "other", "x", "f.toml"));
}

TEST(Fingerprint, IsFnv1a64) {
  // Published FNV-1a 64 test vectors.
  EXPECT_EQ(fingerprint(""), "fnv1a64:cbf29ce484222325");
  EXPECT_EQ(fingerprint("a"), "fnv1a64:af63dc4c8601ec8c");
  EXPECT_FALSE(skinsim_version().empty());
}

TEST(Junit, EscapesXml) {
  EXPECT_EQ(escape_markup("a<b>&\"c'\n\x01"), "a&lt;b&gt;&amp;&quot;c&#39;&#10;?");
}

TEST(Junit, OneTestcasePerLimitAndFailuresCounted) {
  CheckReport report;
  BudgetOutcome b{"x&y", "ipad4", {}, 1.5};
  LimitResult ok;
  ok.limit.metric = "skin.ms";
  ok.limit.text = "<= 4";
  ok.passed = true;
  LimitResult bad = ok;
  bad.passed = false;
  bad.message = "skin.ms rose <a lot>";
  b.limits = {ok, bad, bad};
  report.budgets.push_back(b);
  const std::string xml = junit_xml(report, "f.toml");
  EXPECT_NE(xml.find(R"(<testsuites name="f.toml" tests="3" failures="2")"), std::string::npos);
  EXPECT_NE(xml.find(R"(<testsuite name="x&amp;y" tests="3" failures="2")"), std::string::npos);
  EXPECT_NE(xml.find(R"(name="skin.ms &lt;= 4")"), std::string::npos);
  EXPECT_NE(xml.find(R"(message="skin.ms rose &lt;a lot&gt;")"), std::string::npos);
  std::size_t cases = 0;
  for (std::size_t p = xml.find("<testcase "); p != std::string::npos;
       p = xml.find("<testcase ", p + 1)) {
    ++cases;
  }
  EXPECT_EQ(cases, 3u);
}

}  // namespace
}  // namespace skinsim::budget
