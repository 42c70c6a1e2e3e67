// Every reader of a user-named input against files that are not a sane regular file: each
// must end in a UserError naming the file, quickly, without blocking or reading without end.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <functional>

#include "budget/baseline_file.h"
#include "budget/budget_file.h"
#include "budget/device_fingerprint.h"
#include "driver/sweep_file.h"
#include "gpu_model/profile_loader.h"
#include "reports/sweep_table.h"
#include "scratch_dir.h"
#include "util/user_error.h"

namespace skinsim::io {
namespace {

namespace fs = std::filesystem;

struct Reader {
  const char* name;
  const char* extension;
  std::function<void(const std::string&)> read;
};

const Reader kReaders[] = {
    {"device_profile", ".toml",
     [](const std::string& p) { gpu_model::load_device_profile(p, ""); }},
    {"budget_file", ".toml", [](const std::string& p) { budget::load_budget_file(p); }},
    {"baseline", ".json", [](const std::string& p) { budget::load_baseline(p); }},
    {"sweep_file", ".toml", [](const std::string& p) { driver::parse_sweep_file(p); }},
    {"device_fingerprint", ".toml", [](const std::string& p) { budget::file_fingerprint(p); }},
    {"sweep_results", ".json", [](const std::string& p) { reports::read_sweep_json(p); }},
};

// Makes the bad input at `path`; returns false if it cannot be made here (skip).
struct BadInput {
  const char* name;
  std::function<bool(const fs::path&)> make;
};

const BadInput kBadInputs[] = {
    {"directory", [](const fs::path& p) { return fs::create_directory(p); }},
    {"fifo", [](const fs::path& p) { return ::mkfifo(p.c_str(), 0600) == 0; }},
    {"dev_zero",
     [](const fs::path& p) {
       fs::create_symlink("/dev/zero", p);
       return true;
     }},
    {"oversized",
     [](const fs::path& p) {
       std::ofstream(p) << "# sparse\n";
       fs::resize_file(p, std::uintmax_t{65} << 20);  // sparse: no real disk use
       return true;
     }},
    {"missing", [](const fs::path&) { return true; }},
    {"unreadable",
     [](const fs::path& p) {
       std::ofstream(p) << "x = 1\n";
       fs::permissions(p, fs::perms::none);
       return ::geteuid() != 0;  // root reads it anyway
     }},
    {"below_a_file", [](const fs::path&) { return true; }},  // handled in the test: PATH/child
};

// Test names and failure output show the case names, not the structs' bytes.
void PrintTo(const Reader& reader, std::ostream* os) {
  *os << reader.name;
}
void PrintTo(const BadInput& bad, std::ostream* os) {
  *os << bad.name;
}

class InputReaders : public ::testing::TestWithParam<std::tuple<Reader, BadInput>> {};

TEST_P(InputReaders, BadInputIsAUserErrorNamingTheFile) {
  const auto& [reader, bad] = GetParam();
  const fs::path dir = testing::make_scratch_dir();
  fs::path path = dir / (std::string("input") + reader.extension);
  if (!bad.make(path)) GTEST_SKIP() << bad.name << " cannot be made here";
  if (std::string(bad.name) == "below_a_file") {
    std::ofstream(dir / "plain") << "x";
    path = dir / "plain" / (std::string("input") + reader.extension);
  }
  const auto start = std::chrono::steady_clock::now();
  try {
    reader.read(path.string());
    FAIL() << reader.name << " accepted " << bad.name;
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(AllReaders, InputReaders,
                         ::testing::Combine(::testing::ValuesIn(kReaders),
                                            ::testing::ValuesIn(kBadInputs)),
                         [](const auto& test_info) {
                           return std::string(std::get<0>(test_info.param).name) + "_" +
                                  std::get<1>(test_info.param).name;
                         });

}  // namespace
}  // namespace skinsim::io
