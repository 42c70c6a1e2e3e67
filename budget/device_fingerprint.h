// A fingerprint of a device profile file, so a baseline can tell it was made with the same
// figures (64-bit FNV-1a of the file's bytes, hex).
#pragma once

#include <string>
#include <string_view>

namespace skinsim::budget {

std::string fingerprint(std::string_view bytes);
// Throws BudgetError naming the file when it cannot be read.
std::string file_fingerprint(const std::string& path);

// The project version this binary was built from (CMake project(VERSION)).
std::string skinsim_version();

}  // namespace skinsim::budget
