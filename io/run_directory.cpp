#include "io/run_directory.h"

#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>
#include <utility>
#include <vector>

#include "io/atomic_file.h"
#include "io/json_input.h"
#include "io/temp_files.h"
#include "util/text.h"

namespace skinsim::io {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail_output(const std::string& option, const fs::path& dir,
                              const std::string& why) {
  throw OutputError(fmt::format("{} {}: {}", option, sanitized(dir.string(), 4096), why));
}

// Every entry below `dir` (symlinks not followed), relative to it, but the marker.
std::set<std::string> entries_below(const fs::path& dir) {
  std::set<std::string> entries;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir)) {
    const std::string relative = e.path().lexically_relative(dir).generic_string();
    if (relative != kOutputMarker) entries.insert(relative);
  }
  return entries;
}

// "thesis.tex, src/ and 3 more": what a refused directory holds, for the message.
std::string describe(const fs::path& dir, const std::vector<std::string>& names) {
  constexpr std::size_t kShown = 5;
  std::string text;
  for (std::size_t i = 0; i < std::min(names.size(), kShown); ++i) {
    std::error_code ec;
    const bool is_dir = fs::is_directory(fs::symlink_status(dir / names[i], ec));
    text += (i ? ", " : "") + sanitized(names[i], 200) + (is_dir ? "/" : "");
  }
  if (names.size() > kShown) text += fmt::format(" and {} more", names.size() - kShown);
  return text;
}

// The marker's kind and listed files; nullopt kind ("") when it is missing or not one.
std::pair<std::string, std::set<std::string>> read_marker(const fs::path& dir) {
  try {
    const nlohmann::json j = parse_json(read_own_file(dir / kOutputMarker, "output marker"),
                                        "output marker", dir / kOutputMarker);
    std::set<std::string> files;
    for (const nlohmann::json& f : j.value("files", nlohmann::json::array())) {
      files.insert(f.get<std::string>());
    }
    return {j.at("kind").get<std::string>(), std::move(files)};
  } catch (const std::exception&) {
    return {};
  }
}

}  // namespace

void check_output_directory(const fs::path& dir, const std::string& kind, bool listed_only,
                            const std::string& option) {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(dir, ec);
  if (!fs::exists(status)) return;
  if (fs::is_symlink(status)) fail_output(option, dir, "is a symlink; name the directory itself");
  if (!fs::is_directory(status)) fail_output(option, dir, "exists and is not a directory");
  std::vector<std::string> top;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    top.push_back(e.path().filename().string());
  }
  if (top.empty()) return;
  std::sort(top.begin(), top.end());
  const auto [marked, listed] = read_marker(dir);
  if (marked.empty()) {
    fail_output(
        option, dir,
        fmt::format("is not empty and not a skinsim {} directory (no {} marker); it holds {}: "
                    "refusing to write into it, choose another {}",
                    kind, kOutputMarker, describe(dir, top), option));
  }
  if (marked != kind) {
    fail_output(
        option, dir,
        fmt::format("is a skinsim {} directory, not a {} directory: refusing to write into it, "
                    "choose another {}",
                    sanitized(marked, 40), kind, option));
  }
  if (!listed_only) return;
  std::vector<std::string> foreign;
  for (const std::string& entry : entries_below(dir)) {
    if (!listed.contains(entry)) foreign.push_back(entry);
  }
  if (!foreign.empty()) {
    fail_output(
        option, dir,
        fmt::format("holds files skinsim {} did not write ({}): refusing to replace it, move "
                    "them or choose another {}",
                    kind, describe(dir, foreign), option));
  }
}

void claim_output_directory(const fs::path& dir, const std::string& kind,
                            const std::string& option) {
  check_output_directory(dir, kind, /*listed_only=*/false, option);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) fail_output(option, dir, "cannot create it: " + ec.message());
  if (!fs::exists(fs::symlink_status(dir / kOutputMarker, ec))) {
    write_file_atomically(dir / kOutputMarker, nlohmann::json{{"kind", kind}}.dump() + "\n");
  }
}

RunDirectory::RunDirectory(const fs::path& out, std::string kind)
    : out_(out.empty() ? out : fs::absolute(out).lexically_normal()), kind_(std::move(kind)) {
  // fs::absolute("") is the working directory, which is not what an empty --out asks for.
  if (out_.empty()) fail_output("--out", out_, "empty path: name the output directory");
  // "dir/", "." and "sub/.." name a directory by its parent's entry, which is what is swapped.
  if (out_.filename().empty() && out_ != out_.root_path()) out_ = out_.parent_path();
  check_output_directory(out_, kind_, /*listed_only=*/true);
  const fs::path parent = out_.parent_path().empty() ? fs::path(".") : out_.parent_path();
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec) fail_output("--out", out_, "cannot create " + parent.string() + ": " + ec.message());
  remove_stale_temporaries(parent);
  staging_ = temporary_path_beside(out_);
  if (!fs::create_directory(staging_, ec)) {
    fail_output("--out", out_, "cannot create " + staging_.string() + ": " + ec.message());
  }
}

RunDirectory::~RunDirectory() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

void RunDirectory::commit() {
  const std::set<std::string> written = entries_below(staging_);
  write_file_atomically(staging_ / kOutputMarker,
                        nlohmann::json{{"kind", kind_}, {"files", written}}.dump(1) + "\n");
  // Again: it may have changed while the command worked (a user saved a file into it).
  check_output_directory(out_, kind_, /*listed_only=*/true);
  std::error_code ec;
  fs::path previous;
  if (fs::exists(out_)) {
    previous = temporary_path_beside(out_);
    fs::rename(out_, previous, ec);
    if (ec) fail_output("--out", out_, "cannot move the previous output aside: " + ec.message());
  }
  fs::rename(staging_, out_, ec);
  if (ec) {
    const std::string why = ec.message();
    std::error_code ignored;
    if (!previous.empty()) fs::rename(previous, out_, ignored);  // put the previous one back
    fail_output("--out", out_, "cannot move the new output into place: " + why);
  }
  committed_ = true;
  if (!previous.empty()) fs::remove_all(previous, ec);  // a leftover is cleaned up next run
}

}  // namespace skinsim::io
