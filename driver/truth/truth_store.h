// Truths kept like references (reference_store.h): a path-traced truth takes seconds to hours
// to render, so one rendering serves every later `run --truth cached` of the same view. A truth
// depends only on what Blender is given, so its key is a digest of that: the exported scene
// (truth_scene.h: triangles, camera, lights, materials, skin parameters, resolution), the
// samples, the Cycles script, the two seeds and the Blender version (the first line of
// `blender --version`: another release's Cycles is another judge). It names no build, host or
// path, so a truth rendered on another machine (a bigger one, a Slurm job) by the same
// exporter and Blender has the same key and can be dropped into this store
// (docs/validation.md); a different export or Blender is a different key.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "image/image.h"

namespace skinsim::driver {

// A truth as skinsim judges with it: display images (truth_image.h: display_image), the truth
// and, when known, another seed's rendering of the same scene for its noise floor.
struct TruthImages {
  image::Image image;
  std::optional<image::Image> second;
};

// The key of the truth of the scene exported to `scene_dir` (write_truth_scene; `exported`:
// its scene.json as returned) rendered by `script` in `blender` (its version line) with
// `seed` and, for the noise floor, seed + 1. The sample count is the key's "samples" alone
// (not in its scene digest), so a key can be asked for with other samples and seeds
// (with_samples). Throws UserError naming a file it cannot read.
nlohmann::json truth_key(const nlohmann::json& exported, const std::filesystem::path& scene_dir,
                         const std::filesystem::path& script, int seed, const std::string& blender);

// `key` of the same view and judge with other samples and seeds (seed, seed + 1).
nlohmann::json with_samples(nlohmann::json key, int samples, int seed);

// A kept truth as loading it found it (as KeptReference).
struct KeptTruth {
  std::optional<TruthImages> images;  // verified against its marker, with `second`
  std::string discarded;              // why a copy that was there was not used
};

class TruthStore {
 public:
  // Two 8-bit images a truth: 2048x1536 ones take about 10 MB.
  static constexpr int kDefaultCapacity = 8;

  explicit TruthStore(std::filesystem::path dir, int capacity = kDefaultCapacity);

  // The store in the truths/ folder of the cache directory (cache_directory), if any.
  static std::optional<TruthStore> from_environment();

  // The width x height truth kept under `key`, when its marker is a regular file (not a
  // symlink) holding `key` and the sizes and XXH3 digest of images that are regular files
  // with those pixels; it then counts as just used. Anything else is discarded, saying why.
  KeptTruth load(const nlohmann::json& key, int width, int height) const;

  // Keeps `images` (with `second`) under `key`, each file written to a temporary and renamed
  // over its entry (never through a symlink), the marker last; then evicts beyond the capacity.
  // Returns why it could not be kept (a full disk, a read-only cache), empty when it was.
  std::string keep(const nlohmann::json& key, const TruthImages& images) const;

  // The marker file of `key`: truth_<FNV-1a of the key>.json, beside .png and _second.png.
  std::filesystem::path marker(const nlohmann::json& key) const;

  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path file(const nlohmann::json& key, const std::string& suffix) const;

  std::filesystem::path dir_;
  int capacity_;
};

}  // namespace skinsim::driver
