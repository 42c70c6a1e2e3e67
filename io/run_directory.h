// Output directories a command owns. A command writes only into a directory that is missing,
// empty, or marked as its own kind of output by a marker file it wrote there; anything else is
// refused (OutputError naming the directory and what is in it), so `--out ~` or a directory
// of a different kind (a run's, a sweep's) is never written into or deleted.
//
// A run's, export's or comparison's directory is replaced whole: the command writes into a
// fresh staging directory beside --out, which is swapped in only when it has succeeded. A
// failed command leaves the previous directory untouched, so a directory never mixes the files
// of two runs; and as the marker lists every file the command wrote, a previous directory
// holding anything else (a file a user added) is refused rather than deleted.
#pragma once

#include <filesystem>
#include <string>

namespace skinsim::io {

// The marker file: JSON {"kind": <kind>, "files": [<relative paths written>]}.
inline constexpr const char* kOutputMarker = ".skinsim-output";

// Throws OutputError unless `dir` is missing, empty, or marked as `kind`'s output ("run",
// "sweep", ...) and, with `listed_only`, holds nothing but the files its marker lists.
// `option` names the command-line option in the message.
void check_output_directory(const std::filesystem::path& dir, const std::string& kind,
                            bool listed_only, const std::string& option = "--out");

// For commands that write into their directory in place (a sweep resumes in it):
// check_output_directory, then creates `dir` and marks it as `kind`'s when it is not yet.
void claim_output_directory(const std::filesystem::path& dir, const std::string& kind,
                            const std::string& option = "--out");

class RunDirectory {
 public:
  // Checks that `out` may be replaced by `kind`'s output (check_output_directory with
  // listed_only), removes stale temporaries beside it and creates the staging directory.
  explicit RunDirectory(const std::filesystem::path& out, std::string kind = "run");
  // Removes the staging directory unless commit() succeeded.
  ~RunDirectory();
  RunDirectory(const RunDirectory&) = delete;
  RunDirectory& operator=(const RunDirectory&) = delete;

  // Where the command writes its files until commit().
  const std::filesystem::path& staging() const { return staging_; }
  // Marks the staging directory (listing what it holds) and renames it to `out`; the previous
  // directory is checked again, moved aside and deleted only once the new one is in place.
  void commit();

 private:
  std::filesystem::path out_;
  std::string kind_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

}  // namespace skinsim::io
