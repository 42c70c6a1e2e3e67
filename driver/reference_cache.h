// What a reference frame kept on disk must match to be reused, and loading it: a sweep keeps
// its references in refs/ (sweep_reference.h), a run keeps its own beside its frame
// (frame_job.h), and both reuse a kept copy only when its marker equals the one here.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

#include "driver/frame_quality.h"
#include "driver/scene_source.h"
#include "pipeline/config.h"

namespace skinsim::driver {

// Where a run's or a sweep's reference came from.
enum class ReferenceSource {
  kKept,      // the output directory's own copy: the sweep's refs/, the replaced run's
  kStore,     // the user's reference store (reference_store.h), shared by all output directories
  kRendered,  // rendered, as neither had it
};

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

// Loads a reference image and its skin mask (as quality::save_png and save_mask_png wrote
// them) into `out`: false if either is missing or damaged or their sizes differ. The image
// is the 8-bit one written, so metrics against it are those against the rendered reference.
bool load_reference(const std::filesystem::path& image, const std::filesystem::path& mask,
                    ReferenceImages& out);

// load_reference of a copy whose marker file (a .json beside it) holds `expected`
// (reference_marker): nullopt when the marker is missing, unreadable or another, or the
// images do not load. What a sweep's refs/ and the reference store keep.
std::optional<ReferenceImages> load_marked_reference(const std::filesystem::path& marker,
                                                     const nlohmann::json& expected,
                                                     const std::filesystem::path& image,
                                                     const std::filesystem::path& mask);

}  // namespace skinsim::driver
