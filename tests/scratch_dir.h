// A test program's scratch directory: one per process under the system's temporary directory
// (ctest runs each test in a process of its own, so two never share one), removed with
// everything in it when the program exits, so runs of the suite leave nothing behind.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace skinsim::testing {

// `<tmp>/<prefix>_<pid>`, created on the first call; later calls return the same directory.
inline const std::filesystem::path& scratch_root(const std::string& prefix) {
  struct Root {
    std::filesystem::path path;
    ~Root() {
      std::error_code ignored;  // nothing to report to at exit; a leftover is harmless
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Root root{std::filesystem::temp_directory_path() /
                         (prefix + "_" + std::to_string(::getpid()))};
  std::filesystem::create_directories(root.path);
  return root.path;
}

}  // namespace skinsim::testing
