// The reference frame of a sweep, rendered once per (scene, resolution, reference knobs) and
// kept in the sweep directory (refs/), so a resumed sweep does not render it again, and in the
// user's reference store, so another sweep or run does not either.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>

#include "driver/frame/frame_quality.h"
#include "driver/frame/reference_cache.h"
#include "driver/frame/reference_store.h"
#include "driver/frame/scene_source.h"
#include "pipeline/config.h"
#include "pipeline/gpu_scene.h"

namespace skinsim::driver {

// File stem of the reference a resolved configuration is compared against, e.g.
// "reference_2048x1536_1f0c...": from its fingerprint (reference_cache.h; `scene`:
// scene_fingerprint), so configurations that differ only in knobs the reference does not
// read share it.
std::string reference_stem(const pipeline::PipelineConfig& resolved, const nlohmann::json& scene);

// refs/<stem>.png, relative to the sweep directory (its skin mask: reference_mask_path).
std::string reference_image_path(const std::string& stem);

// Loads refs/<stem>.png and its skin mask from `refs_dir` if its marker vouches for it
// (load_marked_reference: a damaged, replaced or planted copy is discarded with a note on
// `notes`), else takes it from `store` (when given and holding it), else renders the reference with
// `threads` host threads; the last two write it to `refs_dir` (atomically; the .json marker
// last), and a rendered one is also kept in `store`. `source` (optional) tells which
// happened. All paths give bit-identical images. Processes sharing `refs_dir` take turns
// through a lock file (refs/<stem>.lock): one renders, the others wait (saying so on `notes`,
// if given) and load. Where the reference came from, and how long a render took, is said on
// `notes`.
ReferenceImages cached_reference(const pipeline::GpuScene& scene,
                                 const pipeline::PipelineConfig& resolved,
                                 const nlohmann::json& scene_fingerprint,
                                 const std::filesystem::path& refs_dir, int threads,
                                 const ReferenceStore* store = nullptr,
                                 ReferenceSource* source = nullptr, std::FILE* notes = nullptr);

}  // namespace skinsim::driver
