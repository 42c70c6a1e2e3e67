#include "io/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <set>
#include <sstream>

#include "full_disk.h"
#include "io/temp_files.h"
#include "scratch_dir.h"

namespace skinsim::io {
namespace {

namespace fs = std::filesystem;

// The directory holds exactly `names`: no temporary left behind.
void expect_only(const fs::path& dir, std::set<std::string> names) {
  std::set<std::string> found;
  for (const auto& e : fs::directory_iterator(dir)) found.insert(e.path().filename().string());
  EXPECT_EQ(found, names);
}

TEST(AtomicFile, WritesAndReplacesARegularFile) {
  const fs::path dir = testing::make_scratch_dir();
  write_file_atomically(dir / "a.json", "first");
  write_file_atomically(dir / "a.json", "second");
  EXPECT_EQ(testing::read_whole(dir / "a.json"), "second");
  expect_only(dir, {"a.json"});
}

TEST(AtomicFile, WritesThroughASymlinkToItsTarget) {
  const fs::path dir = testing::make_scratch_dir();
  fs::create_directory(dir / "real");
  std::ofstream(dir / "real" / "report.xml") << "old";
  fs::create_symlink("real/report.xml", dir / "link.xml");
  fs::create_symlink("link.xml", dir / "link2.xml");  // a chain of links
  write_file_atomically(dir / "link2.xml", "new");
  EXPECT_TRUE(fs::is_symlink(dir / "link.xml"));
  EXPECT_TRUE(fs::is_symlink(dir / "link2.xml"));
  EXPECT_EQ(testing::read_whole(dir / "real" / "report.xml"), "new");
  expect_only(dir / "real", {"report.xml"});
}

TEST(AtomicFile, DanglingSymlinkCreatesItsTarget) {
  const fs::path dir = testing::make_scratch_dir();
  fs::create_symlink("target.txt", dir / "link.txt");
  write_file_atomically(dir / "link.txt", "made");
  EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
  EXPECT_EQ(testing::read_whole(dir / "target.txt"), "made");
}

TEST(AtomicFile, DeviceIsWrittenInPlaceNeverReplaced) {
  // /dev/null through a symlink: written, and still a character device afterwards.
  const fs::path dir = testing::make_scratch_dir();
  fs::create_symlink("/dev/null", dir / "sink");
  write_file_atomically(dir / "sink", "discarded");
  struct stat st {};
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  expect_only(dir, {"sink"});
}

TEST(AtomicFile, FullDeviceReportsTheFailureAndStaysADevice) {
  const fs::path dir = testing::make_scratch_dir();
  fs::create_symlink("/dev/full", dir / "full");
  try {
    write_file_atomically(dir / "full", "no room");
    FAIL() << "expected OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("No space left"), std::string::npos) << e.what();
  }
  struct stat st {};
  ASSERT_EQ(::stat("/dev/full", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
}

TEST(AtomicFile, FifoWithoutReaderIsAnErrorNotAHang) {
  const fs::path dir = testing::make_scratch_dir();
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
  const auto start = std::chrono::steady_clock::now();
  try {
    write_file_atomically(dir / "pipe", "x");
    FAIL() << "expected OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("nobody is reading"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
  struct stat st {};
  ASSERT_EQ(::stat((dir / "pipe").c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

TEST(AtomicFile, DirectoryTargetIsRefused) {
  const fs::path dir = testing::make_scratch_dir();
  fs::create_directory(dir / "out.json");
  EXPECT_THROW(write_file_atomically(dir / "out.json", "x"), OutputError);
  EXPECT_TRUE(fs::is_directory(dir / "out.json"));
}

TEST(AtomicFile, FailureMessageNamesTheRealReason) {
  const fs::path dir = testing::make_scratch_dir();
  try {
    write_file_atomically(dir / "missing" / "a.json", "x");
    FAIL() << "expected OutputError";
  } catch (const OutputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find((dir / "missing" / "a.json").string()), std::string::npos) << message;
    EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
    EXPECT_EQ(message.find("Success"), std::string::npos) << message;
  }
}

TEST(AtomicFile, FullDiskKeepsTheOldFileAndLeavesNoTemporary) {
  const fs::path dir = testing::make_scratch_dir();
  write_file_atomically(dir / "result.json", "previous run");
  const std::string big(64 * 1024, 'x');
  const std::string error =
      testing::error_on_full_disk(4096, [&] { write_file_atomically(dir / "result.json", big); });
  EXPECT_NE(error.find("cannot write " + (dir / "result.json").string()), std::string::npos)
      << error;
  EXPECT_NE(error.find("File too large"), std::string::npos) << error;
  EXPECT_EQ(testing::read_whole(dir / "result.json"), "previous run");
  expect_only(dir, {"result.json"});
}

}  // namespace
}  // namespace skinsim::io
