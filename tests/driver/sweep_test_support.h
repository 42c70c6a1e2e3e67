// Shared by the sweep tests: a fresh output directory per test, run options for tiny sweeps,
// and reading a written file back.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "driver/sweep/sweep_run.h"
#include "tests/test_paths.h"

namespace skinsim::driver::test {

// <build>/tests/driver/sweep_test_out/<name>, emptied; kept after the run for inspection.
inline std::filesystem::path out_dir(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::path(test_paths::kTestsBinaryDir) / "driver" / "sweep_test_out" / name;
  std::filesystem::remove_all(dir);
  return dir;
}

// Silent, with the source tree's device profiles.
inline SweepRunOptions options(const std::filesystem::path& dir, int threads) {
  SweepRunOptions o;
  o.out_dir = dir.string();
  o.data_dir = test_paths::kDataDir;
  o.threads = threads;
  o.progress = nullptr;
  return o;
}

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace skinsim::driver::test
