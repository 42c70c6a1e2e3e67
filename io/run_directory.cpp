#include "io/run_directory.h"

#include <fmt/format.h>

#include "io/atomic_file.h"
#include "io/temp_files.h"

namespace skinsim::io {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const fs::path& out, const std::string& why) {
  throw OutputError(fmt::format("output directory {}: {}", out.string(), why));
}

// A previous skinsim run's directory: marked, or (before the marker existed) holding a result.
bool is_run_directory(const fs::path& dir) {
  return fs::is_regular_file(dir / kRunMarker) || fs::is_regular_file(dir / "result.json");
}

void check_replaceable(const fs::path& out) {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(out, ec);
  if (!fs::exists(status)) return;
  if (fs::is_symlink(status)) fail(out, "is a symlink; name the directory itself");
  if (!fs::is_directory(status)) fail(out, "exists and is not a directory");
  if (fs::is_empty(out, ec) || is_run_directory(out)) return;
  fail(out, fmt::format("is not empty and not a skinsim run directory (no {} or result.json); "
                        "refusing to replace it, choose another --out",
                        kRunMarker));
}

}  // namespace

RunDirectory::RunDirectory(const fs::path& out) : out_(fs::absolute(out).lexically_normal()) {
  // "dir/", "." and "sub/.." name a directory by its parent's entry, which is what is swapped.
  if (out_.filename().empty() && out_ != out_.root_path()) out_ = out_.parent_path();
  check_replaceable(out_);
  const fs::path parent = out_.parent_path().empty() ? fs::path(".") : out_.parent_path();
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec) fail(out_, "cannot create " + parent.string() + ": " + ec.message());
  remove_stale_temporaries(parent);
  staging_ = temporary_path_beside(out_);
  if (!fs::create_directory(staging_, ec)) {
    fail(out_, "cannot create " + staging_.string() + ": " + ec.message());
  }
}

RunDirectory::~RunDirectory() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

void RunDirectory::commit() {
  write_file_atomically(staging_ / kRunMarker, "skinsim run output\n");
  check_replaceable(out_);  // again: it may have changed while the run worked
  std::error_code ec;
  fs::path previous;
  if (fs::exists(out_)) {
    previous = temporary_path_beside(out_);
    fs::rename(out_, previous, ec);
    if (ec) fail(out_, "cannot move the previous run aside: " + ec.message());
  }
  fs::rename(staging_, out_, ec);
  if (ec) {
    const std::string why = ec.message();
    std::error_code ignored;
    if (!previous.empty()) fs::rename(previous, out_, ignored);  // put the previous run back
    fail(out_, "cannot move the new run into place: " + why);
  }
  committed_ = true;
  if (!previous.empty()) fs::remove_all(previous, ec);  // a leftover is cleaned up next run
}

}  // namespace skinsim::io
