#include "io/run_directory.h"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

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
            (std::set<std::string>{kOutputMarker, "second.png", "result.json"}));
  EXPECT_EQ(names_in(root), std::set<std::string>{"out"});  // no staging or old copy left
}

TEST(RunDirectory, FailedRunLeavesThePreviousRunUntouchedAndNoTemporary) {
  const fs::path root = testing::make_scratch_dir();
  simulate_run(root / "out", "first", false);
  EXPECT_THROW(simulate_run(root / "out", "second", true), std::runtime_error);
  EXPECT_EQ(names_in(root / "out"),
            (std::set<std::string>{kOutputMarker, "first.png", "result.json"}));
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

// What a command finds in --out, and whether it may write there: only a missing or empty
// directory, or one marked as its own kind by the marker it wrote, holding only what it wrote.
struct Found {
  const char* name;
  std::function<void(const fs::path&)> make;  // in the directory `out`
  const char* refused;                        // part of the message, or nullptr: accepted
};

std::vector<Found> found_cases() {
  const auto file = [](const fs::path& path, const std::string& text = "x") {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
  };
  return {
      {"missing", [](const fs::path&) {}, nullptr},
      {"empty", [](const fs::path& out) { fs::create_directories(out); }, nullptr},
      {"own_run", [](const fs::path& out) { simulate_run(out, "first", false); }, nullptr},
      {"result_json_is_no_marker",  // a user's directory that happens to hold a result.json
       [&](const fs::path& out) {
         file(out / "result.json", "{}");
         file(out / "thesis.tex");
         file(out / "src" / "main.c");
       },
       "it holds result.json, src/, thesis.tex"},
      {"another_kind",
       [&](const fs::path& out) {
         RunDirectory other(out, "export");
         other.commit();
       },
       "is a skinsim export directory, not a run directory"},
      {"a_file_added_to_a_run",
       [&](const fs::path& out) {
         simulate_run(out, "first", false);
         file(out / "notes.txt");
       },
       "holds files skinsim run did not write (notes.txt)"},
      {"a_file_added_below",
       [&](const fs::path& out) {
         simulate_run(out, "first", false);
         file(out / "sub" / "notes.txt");
       },
       "did not write (sub/, sub/notes.txt)"},
      {"garbage_marker", [&](const fs::path& out) { file(out / kOutputMarker, "{garbage"); },
       "no .skinsim-output marker"},
      {"deep_marker",
       [&](const fs::path& out) { file(out / kOutputMarker, std::string(100000, '[')); },
       "no .skinsim-output marker"},
      {"symlink", [](const fs::path& out) { fs::create_directory_symlink("/", out); },
       "is a symlink"},
      {"file", [&](const fs::path& out) { file(out); }, "exists and is not a directory"},
  };
}

// Every path below `dir` (not following a symlink `dir`).
std::set<std::string> tree(const fs::path& dir) {
  std::set<std::string> paths;
  if (!fs::is_directory(fs::symlink_status(dir))) return paths;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    paths.insert(entry.path().string());
  }
  return paths;
}

void PrintTo(const Found& found, std::ostream* os) {
  *os << found.name;
}

class OutputOwnership : public ::testing::TestWithParam<Found> {};

TEST_P(OutputOwnership, WritesOnlyWhereItMayAndDeletesNothingElse) {
  const fs::path root = testing::make_scratch_dir();
  const fs::path out = root / "out";
  GetParam().make(out);
  const std::set<std::string> before = tree(out);
  try {
    simulate_run(out, "second", false);
    EXPECT_EQ(GetParam().refused, nullptr) << "accepted";
  } catch (const OutputError& e) {
    ASSERT_NE(GetParam().refused, nullptr) << e.what();
    EXPECT_NE(std::string(e.what()).find(GetParam().refused), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(out.string()), std::string::npos) << e.what();
    EXPECT_EQ(tree(out), before);
  }
  if (fs::is_symlink(fs::symlink_status(out))) fs::remove(out);  // not what it points to
}

INSTANTIATE_TEST_SUITE_P(Cases, OutputOwnership, ::testing::ValuesIn(found_cases()),
                         [](const auto& test_info) { return std::string(test_info.param.name); });

TEST(ClaimOutputDirectory, MarksANewOneAndKeepsToItsKind) {
  const fs::path root = testing::make_scratch_dir();
  claim_output_directory(root / "sweep", "sweep");
  std::ofstream(root / "sweep" / "results.json") << "{}";
  EXPECT_NO_THROW(claim_output_directory(root / "sweep", "sweep"));  // resumed: its own
  EXPECT_THROW(RunDirectory(root / "sweep"), OutputError);           // a run never replaces it
  simulate_run(root / "run", "first", false);
  EXPECT_THROW(claim_output_directory(root / "run", "sweep"), OutputError);
  EXPECT_FALSE(fs::exists(root / "run" / "results.json"));
}

TEST(RunDirectory, AnEmptyPathIsRefused) {
  EXPECT_THROW(RunDirectory(""), OutputError);
}

}  // namespace
}  // namespace skinsim::io
