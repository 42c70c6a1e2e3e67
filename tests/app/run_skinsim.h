// Runs the skinsim binary under test (test_paths::kSkinsimExe) from a CLI test and captures what
// it prints.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

#include "tests/test_paths.h"

namespace skinsim::test {

struct Result {
  int exit_code;
  std::string output;  // stdout + stderr
};

// `skinsim ARGS` through the shell; exit_code is -1 when it did not exit normally.
inline Result run(const std::string& args) {
  const std::string command = std::string(test_paths::kSkinsimExe) + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  EXPECT_NE(pipe, nullptr);
  std::string output;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe)) output += buffer.data();
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

}  // namespace skinsim::test
