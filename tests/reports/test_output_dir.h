// A fresh, per-test output directory under the test's working directory (kept after the run
// so the charts and report can be inspected).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace skinsim::reports::testing {

inline std::string fresh_output_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::current_path() / "reports_test_out" /
                                    (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

}  // namespace skinsim::reports::testing
