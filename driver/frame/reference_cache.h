// What a reference frame kept on disk must match to be reused, and loading it: a sweep keeps
// its references in refs/ (sweep_reference.h), a run keeps its own beside its frame
// (frame_job.h), and the reference store keeps them for every run (reference_store.h); each
// reuses a kept copy only when its marker is the one here and its pixels are those the marker
// describes, as a cache directory may be shared, edited or damaged.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "driver/frame/frame_quality.h"
#include "driver/frame/scene_source.h"
#include "pipeline/config.h"

namespace skinsim::driver {

// Where a run's or a sweep's reference came from.
enum class ReferenceSource {
  kKept,      // the output directory's own copy: the sweep's refs/, the replaced run's
  kStore,     // the user's reference store (reference_store.h), shared by all output directories
  kRendered,  // rendered, as neither had it
};

// Whether `path` itself (not a symlink's target) is a regular file: what a cache reads.
bool is_plain_file(const std::filesystem::path& path);

// What the reference depends on: the knobs marked `reference` in the knob table (the
// resolution, the BRDF parameters, the light and framing: pipeline/knob.h) and the scene
// (`scene`: scene_fingerprint, which reads a scan, so callers compute it once).
// Configurations that differ only in other knobs share a reference.
nlohmann::json reference_fingerprint(const pipeline::PipelineConfig& resolved,
                                     const nlohmann::json& scene);

// The marker a kept reference carries: its fingerprint and the build that rendered it
// (another build may render another image).
nlohmann::json reference_marker(const pipeline::PipelineConfig& resolved,
                                const nlohmann::json& scene);

// The skin mask kept beside a reference image: <image stem>_skin.png.
std::string reference_mask_path(const std::string& reference_image);

// A kept copy of a reference as loading it found it.
struct KeptReference {
  std::optional<ReferenceImages> images;  // the copy, verified against its marker
  // Why a copy that was there was not used, for a note (the reference is then rendered
  // again): empty when it was used, or when there was none of this reference (no marker, or
  // one of another build or configuration).
  std::string discarded;
};

// The marker a kept copy of `images` carries: `marker` (reference_marker) with, under
// "images", their size and an XXH3 digest of their pixels, so that images replaced, swapped
// or damaged on disk are told from the ones kept.
nlohmann::json kept_reference_marker(const nlohmann::json& marker, const ReferenceImages& images);

// The copy at `image` and its skin mask `mask` whose kept marker is `stored`, when `stored` is
// `expected`'s (reference_marker) and the images are regular files (a symlink is not) of
// width x height whose pixels match the marker's digest. The image is the 8-bit one written,
// so metrics against it are those against the rendered reference.
KeptReference load_kept_reference(const nlohmann::json& stored, const nlohmann::json& expected,
                                  int width, int height, const std::filesystem::path& image,
                                  const std::filesystem::path& mask);

// load_kept_reference with the kept marker read from the file `marker` beside the images (a
// sweep's refs/, the reference store): a marker that is a symlink, not a regular file, not
// JSON or nested beyond io::kMaxJsonDepth is discarded too.
KeptReference load_marked_reference(const std::filesystem::path& marker,
                                    const nlohmann::json& expected, int width, int height,
                                    const std::filesystem::path& image,
                                    const std::filesystem::path& mask);

// Writes `images` to `image` and `mask`, then their kept marker (returned) to `marker`, last,
// so a reader finds either no marker or a complete copy. Each file replaces its directory
// entry (io::replace_file_entry): a symlink planted there is replaced, never written through.
nlohmann::json save_marked_reference(const nlohmann::json& marker, const ReferenceImages& images,
                                     const std::filesystem::path& marker_file,
                                     const std::filesystem::path& image,
                                     const std::filesystem::path& mask);

}  // namespace skinsim::driver
