#include "io/run_directory.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <stdexcept>

#include "io/atomic_file.h"
#include "scratch_dir.h"

namespace skinsim::io {
namespace {

namespace fs = std::filesystem;

std::set<std::string> names_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

void simulate_run(const fs::path& out, const std::string& tag, bool fail) {
  RunDirectory run(out);
  write_file_atomically(run.staging() / (tag + ".png"), tag);
  if (fail) throw std::runtime_error("run failed");
  write_file_atomically(run.staging() / "result.json", tag);
  run.commit();
}

TEST(RunDirectory, SuccessfulRunReplacesThePreviousOneWhole) {
  const fs::path root = testing::make_scratch_dir();
  simulate_run(root / "out", "first", false);
  simulate_run(root / "out", "second", false);
  EXPECT_EQ(names_in(root / "out"),
            (std::set<std::string>{kRunMarker, "second.png", "result.json"}));
  EXPECT_EQ(names_in(root), std::set<std::string>{"out"});  // no staging or old copy left
}

TEST(RunDirectory, FailedRunLeavesThePreviousRunUntouchedAndNoTemporary) {
  const fs::path root = testing::make_scratch_dir();
  simulate_run(root / "out", "first", false);
  EXPECT_THROW(simulate_run(root / "out", "second", true), std::runtime_error);
  EXPECT_EQ(names_in(root / "out"),
            (std::set<std::string>{kRunMarker, "first.png", "result.json"}));
  EXPECT_EQ(names_in(root), std::set<std::string>{"out"});
}

TEST(RunDirectory, EmptyOrMissingDirectoryIsAccepted) {
  const fs::path root = testing::make_scratch_dir();
  fs::create_directory(root / "empty");
  simulate_run(root / "empty", "a", false);
  simulate_run(root / "new" / "nested", "a", false);
  EXPECT_TRUE(fs::exists(root / "empty" / "result.json"));
  EXPECT_TRUE(fs::exists(root / "new" / "nested" / "result.json"));
}

TEST(RunDirectory, ForeignDirectoryIsNeverReplaced) {
  const fs::path root = testing::make_scratch_dir();
  fs::create_directory(root / "home");
  std::ofstream(root / "home" / "thesis.tex") << "precious";
  try {
    RunDirectory run(root / "home");
    FAIL() << "expected OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a skinsim run directory"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(names_in(root / "home"), std::set<std::string>{"thesis.tex"});
  EXPECT_EQ(names_in(root), std::set<std::string>{"home"});
  std::ofstream(root / "file") << "x";
  EXPECT_THROW(RunDirectory(root / "file"), OutputError);
}

}  // namespace
}  // namespace skinsim::io
