// Paths the tests need that differ from one clone or build directory to another. They are
// defined in one generated file (test_paths.cpp, written by tests/CMakeLists.txt) instead of
// compile definitions, so every other test object is the same in every clone and ccache
// shares it (scripts/ccache-env.sh).
#pragma once

namespace skinsim::test_paths {

extern const char* const kDataDir;         // the source tree's data/ (devices, budgets, ...)
extern const char* const kLeePerrySmith;   // ../shared/assets/LeePerrySmith.glb
extern const char* const kSkinsimExe;      // the skinsim binary of this build
extern const char* const kTestsBinaryDir;  // this build's tests/ folder, for test outputs

}  // namespace skinsim::test_paths
