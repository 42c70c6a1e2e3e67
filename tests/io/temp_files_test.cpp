#include "io/temp_files.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>

#include "scratch_dir.h"

namespace skinsim::io {
namespace {

namespace fs = std::filesystem;

// A pid that surely belongs to no process: a child that has exited and been reaped.
pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

// A temporary name as another process (pid) on this host would make it.
// (Built with +=: GCC 12 warns falsely (-Wrestrict) on "." + std::to_string(...).)
std::string dotted(long pid) {
  std::string text = ".";
  text += std::to_string(pid);
  text += '.';
  return text;
}

fs::path temporary_of(const fs::path& target, pid_t pid) {
  std::string name = temporary_path_beside(target).filename().string();
  const std::string own = dotted(::getpid());
  const std::size_t at = name.rfind(own);
  std::string renamed = name.substr(0, at);
  renamed += dotted(pid);
  renamed += name.substr(at + own.size());
  return target.parent_path() / renamed;
}

void touch(const fs::path& path) {
  std::ofstream(path) << "partial";
}

TEST(TempFiles, NamesFollowOnePattern) {
  const fs::path temp = temporary_path_beside("/some/dir/result.json");
  EXPECT_EQ(temp.parent_path(), "/some/dir");
  EXPECT_EQ(temp.filename().string().rfind(".result.json.skinsim-tmp.", 0), 0u) << temp;
  EXPECT_TRUE(is_temporary_name(temp.filename().string()));
  EXPECT_NE(temporary_path_beside("/d/a"), temporary_path_beside("/d/a"));
  EXPECT_FALSE(is_temporary_name("result.json"));
  EXPECT_FALSE(is_temporary_name("result.tmp123.json"));
  EXPECT_TRUE(is_temporary_name(".frame.png.skinsim-tmp.host.42.7.png"));  // writer's extension
  EXPECT_FALSE(is_temporary_name("frame.png.skinsim-tmp.host.42.7"));      // not hidden
  EXPECT_FALSE(is_temporary_name(".frame.png.skinsim-tmp.host.42"));       // no counter
  EXPECT_FALSE(is_temporary_name(".frame.png.skinsim-tmp..42.7"));         // no host
  EXPECT_FALSE(is_temporary_name(".frame.png.skinsim-tmp.host.4x2.7"));    // pid not a number
}

TEST(TempFiles, StaleTemporaryOfADeadProcessIsRemovedLiveOneKept) {
  const fs::path dir = testing::make_scratch_dir();
  const fs::path stale = temporary_of(dir / "frame.png", dead_pid());
  const fs::path stale_dir = temporary_of(dir / "out", dead_pid());
  const fs::path live = temporary_path_beside(dir / "frame.png");  // this process: alive
  const fs::path user_file = dir / ".frame.png.tmp";               // not ours: never touched
  touch(stale);
  fs::create_directory(stale_dir);
  touch(stale_dir / "frame.png");
  touch(live);
  touch(user_file);

  EXPECT_EQ(remove_stale_temporaries(dir), 2);
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_FALSE(fs::exists(stale_dir));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(user_file));
}

TEST(TempFiles, TreeCleanupReachesSubdirectories) {
  const fs::path dir = testing::make_scratch_dir();
  fs::create_directories(dir / "configs" / "c1");
  const fs::path stale = temporary_of(dir / "configs" / "c1" / "config.json", dead_pid());
  touch(stale);
  EXPECT_EQ(remove_stale_temporaries_in_tree(dir), 1);
  EXPECT_FALSE(fs::exists(stale));
}

}  // namespace
}  // namespace skinsim::io
