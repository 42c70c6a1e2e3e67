// References shared by every run and sweep of one user. A reference depends only on its marker
// (reference_cache.h: the scene with a scan's bytes, the knobs marked `reference`, the build),
// so one rendering serves every later `skinsim run` or `skinsim sweep` that asks for the same
// one, whatever its output directory: the store keeps the most recently used references in
// the user's cache directory. A run's or a sweep's own directory still gets its copy, so an
// output directory stands alone; the store only saves rendering it again.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "driver/frame/frame_quality.h"
#include "driver/frame/reference_cache.h"

namespace skinsim::driver {

// The cache directory the environment selects: SKINSIM_CACHE_DIR names it, or is "off" in any
// case ("OFF", "Off") for none; unset or empty, $XDG_CACHE_HOME/skinsim (an absolute
// XDG_CACHE_HOME), else $HOME/.cache/skinsim; none without a home. Throws UserError naming
// SKINSIM_CACHE_DIR when it names something that is not a directory (a file, a dangling
// symlink) or holds a control character. The reference store (below) and the truth store
// (truth_store.h) keep their entries in folders of it.
std::optional<std::filesystem::path> cache_directory();

// Removes the entries of a store in `dir` whose markers (<stem>*.json) were used least
// recently, beyond `capacity`, with their files (the marker's name without ".json", then each
// of `suffixes`). The marker goes first: its files are then no entry. Another process may be
// loading one of them: it then finds it incomplete and renders it.
void evict_least_recent(const std::filesystem::path& dir, const std::string& stem,
                        const std::vector<std::string>& suffixes, int capacity);

class ReferenceStore {
 public:
  // A 2048x1536 reference and its mask take about 2 MB: sixteen are a few tens of MB.
  static constexpr int kDefaultCapacity = 16;

  // References are kept in `dir` (created when the first is kept).
  explicit ReferenceStore(std::filesystem::path dir, int capacity = kDefaultCapacity);

  // The store in the references/ folder of the cache directory (cache_directory), if any.
  static std::optional<ReferenceStore> from_environment();

  // The width x height reference kept under `marker` (reference_marker), when the store holds
  // a copy of it that its marker vouches for (load_marked_reference); it then counts as just
  // used. A damaged, replaced or planted copy is discarded, and `discarded` says why.
  KeptReference load(const nlohmann::json& marker, int width, int height) const;

  // Keeps `images` under `marker` (save_marked_reference: never through a symlink) and removes the
  // least recently used references beyond the capacity. A reference that cannot be kept (a full
  // disk, a read-only cache) is no error for the run: the reason is returned, empty when it was
  // kept.
  std::string keep(const nlohmann::json& marker, const ReferenceImages& images) const;

  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path file(const nlohmann::json& marker, const std::string& suffix) const;
  void evict() const;

  std::filesystem::path dir_;
  int capacity_;
};

}  // namespace skinsim::driver
