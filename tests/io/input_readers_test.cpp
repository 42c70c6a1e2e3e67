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
#include "driver/sweep/run_compare.h"
#include "driver/sweep/sweep_config_result.h"
#include "driver/sweep/sweep_file.h"
#include "driver/sweep/sweep_shard.h"
#include "gpu_model/profile_loader.h"
#include "io/json_input.h"
#include "results/sweep_table.h"
#include "scratch_dir.h"
#include "util/text.h"
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
    {"sweep_results", ".json", [](const std::string& p) { results::read_sweep_json(p); }},
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

// Every JSON input skinsim reads, against text nested far deeper than any real one: a clear
// error naming the file (or, for readers of skinsim's own caches, "no copy"), never a stack
// overflow in the parser or in the recursive code that later walks the tree.
struct JsonReader {
  const char* name;
  std::function<void(const fs::path&)> read;  // throws UserError, or returns when it ignores it
  bool refuses;                               // throws, rather than treating it as absent
};

const JsonReader kJsonReaders[] = {
    {"baseline", [](const fs::path& p) { budget::load_baseline(p); }, true},
    {"sweep_results", [](const fs::path& p) { results::read_sweep_json(p.string()); }, true},
    {"run_result",
     [](const fs::path& p) { driver::compare_outputs(p.parent_path(), p.parent_path(), {}, {}); },
     true},
    {"stored_config", [](const fs::path& p) { EXPECT_FALSE(driver::read_stored_config(p)); },
     false},
    {"shard_status",
     [](const fs::path& p) {
       fs::create_directories(p.parent_path() / "shards");
       fs::copy_file(p, p.parent_path() / "shards" / "shard-0-of-1.json");
       EXPECT_TRUE(driver::read_shard_statuses(p.parent_path()).empty());
     },
     false},
};

void PrintTo(const JsonReader& reader, std::ostream* os) {
  *os << reader.name;
}

class DeepJson : public ::testing::TestWithParam<JsonReader> {};

TEST_P(DeepJson, IsRefusedOrIgnoredNeverACrash) {
  const fs::path dir = testing::make_scratch_dir();
  const fs::path path = dir / "result.json";
  std::ofstream(path) << std::string(100000, '[') << std::string(100000, ']');
  try {
    GetParam().read(path);
    EXPECT_FALSE(GetParam().refuses) << GetParam().name << " accepted it";
  } catch (const UserError& e) {
    EXPECT_TRUE(GetParam().refuses) << e.what();
    EXPECT_NE(std::string(e.what()).find("nests deeper than 64"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(AllJsonReaders, DeepJson, ::testing::ValuesIn(kJsonReaders),
                         [](const auto& test_info) { return std::string(test_info.param.name); });

TEST(JsonInput, NestingUpToTheBoundIsRead) {
  const std::string deepest = std::string(kMaxJsonDepth, '[') + std::string(kMaxJsonDepth, ']');
  EXPECT_NO_THROW(parse_json(deepest, "test", "deepest"));
  EXPECT_THROW(parse_json("[" + deepest + "]", "test", "deeper"), InputError);
  EXPECT_TRUE(parse_json_or_discarded("[" + deepest + "]").is_discarded());
  EXPECT_THROW(parse_json("{garbage", "test", "garbage"), InputError);
}

// Text from files a user may edit, printed: no control character reaches the terminal, and
// a long one is cut at a character boundary, saying how long it was.
TEST(Sanitized, StripsControlCharactersAndCapsTheLength) {
  struct Case {
    std::string in;
    std::size_t max;
    std::string out;
  };
  const Case cases[] = {
      {"node4", 256, "node4"},
      {"a\x1b[31mred\x07", 256, "a?[31mred?"},
      {"tab\tnl\ncr\rdel\x7f", 256, "tab?nl?cr?del?"},
      {"csi\xc2\x9b"
       "31m",
       256, "csi?31m"},                                 // U+009B, C1 CSI in UTF-8
      {"\xc3\xa9t\xc3\xa9", 256, "\xc3\xa9t\xc3\xa9"},  // other UTF-8 kept
      {"abcdef", 3, "abc... (6 bytes)"},
      {"a\xc3\xa9"
       "b",
       2, "a... (4 bytes)"},  // not cut inside the two-byte \xc3\xa9
  };
  for (const Case& c : cases) EXPECT_EQ(sanitized(c.in, c.max), c.out) << c.in;
}

}  // namespace
}  // namespace skinsim::io
