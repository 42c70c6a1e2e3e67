#include "io/free_space.h"

#include <gtest/gtest.h>

#include "scratch_dir.h"
#include "util/user_error.h"

namespace skinsim::io {
namespace {

TEST(FreeSpace, AnOutputThatFitsPasses) {
  EXPECT_NO_THROW(require_free_space(testing::make_scratch_dir(), 1, "skinsim export --out x"));
}

// More than any filesystem holds: the message names the command, the directory and sizes.
TEST(FreeSpace, AnOutputLargerThanTheFreeSpaceIsRefusedBeforeWriting) {
  const std::filesystem::path dir = testing::make_scratch_dir();
  try {
    require_free_space(dir, std::uintmax_t{1} << 62, "skinsim export --out x");
    FAIL() << "4.6 EB fit";
  } catch (const UserError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("skinsim export --out x"), std::string::npos) << message;
    EXPECT_NE(message.find(dir.string()), std::string::npos) << message;
    EXPECT_NE(message.find("4611686018427.4 MB"), std::string::npos) << message;
    EXPECT_NE(message.find("free"), std::string::npos) << message;
  }
}

TEST(FreeSpace, MegabytesAreDecimal) {
  EXPECT_EQ(megabytes(467'200'000), "467.2 MB");
  EXPECT_EQ(megabytes(0), "0.0 MB");
}

}  // namespace
}  // namespace skinsim::io
