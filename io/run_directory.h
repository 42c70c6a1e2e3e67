// A run's output directory, replaced whole: the run writes into a fresh staging directory
// beside --out, which is swapped in only when the run has succeeded. A failed run leaves the
// previous run's directory untouched, so a directory never mixes the files of two runs.
#pragma once

#include <filesystem>

namespace skinsim::io {

// The file that marks a directory as a skinsim run's output, so that only such directories
// (or empty ones) are ever replaced: `--out ~` must never delete a home directory.
inline constexpr const char* kRunMarker = ".skinsim-run";

class RunDirectory {
 public:
  // Checks that `out` may be replaced (missing, empty, or a previous run's directory; else
  // OutputError naming it), removes stale temporaries beside it and creates the staging
  // directory.
  explicit RunDirectory(const std::filesystem::path& out);
  // Removes the staging directory unless commit() succeeded.
  ~RunDirectory();
  RunDirectory(const RunDirectory&) = delete;
  RunDirectory& operator=(const RunDirectory&) = delete;

  // Where the run writes its files until commit().
  const std::filesystem::path& staging() const { return staging_; }
  // Marks the staging directory as a run's and renames it to `out`; the previous directory is
  // moved aside first and deleted only once the new one is in place.
  void commit();

 private:
  std::filesystem::path out_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

}  // namespace skinsim::io
