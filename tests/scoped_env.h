// Sets an environment variable for a scope (or unsets it, for nullopt), then restores what it
// was: tests that point DISPLAY or SKINSIM_SIMD somewhere leave the next test's environment
// as they found it.
#pragma once

#include <cstdlib>
#include <optional>
#include <string>
#include <utility>

namespace skinsim::test {

class ScopedEnv {
 public:
  ScopedEnv(std::string name, const std::optional<std::string>& value) : name_(std::move(name)) {
    if (const char* old = std::getenv(name_.c_str())) old_ = old;
    set(value);
  }
  ~ScopedEnv() { set(old_); }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  void set(const std::optional<std::string>& value) {
    if (value)
      ::setenv(name_.c_str(), value->c_str(), 1);
    else
      ::unsetenv(name_.c_str());
  }

  std::string name_;
  std::optional<std::string> old_;
};

}  // namespace skinsim::test
