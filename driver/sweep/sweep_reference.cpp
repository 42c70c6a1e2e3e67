#include "driver/sweep/sweep_reference.h"

#include <fmt/format.h>

#include <chrono>
#include <fstream>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "driver/frame/reference_cache.h"
#include "driver/sweep/sweep_spec.h"
#include "io/file_lock.h"
#include "pipeline/reference/reference.h"
#include "util/fingerprint.h"

namespace skinsim::driver {

std::string reference_stem(const pipeline::PipelineConfig& resolved, const nlohmann::json& scene) {
  return fmt::format("reference_{}x{}_{}", resolved.width, resolved.height,
                     fnv1a64_hex(reference_fingerprint(resolved, scene).dump()).substr(0, 8));
}

std::string reference_image_path(const std::string& stem) {
  return "refs/" + stem + ".png";
}

ReferenceImages cached_reference(const pipeline::GpuScene& scene,
                                 const pipeline::PipelineConfig& resolved,
                                 const nlohmann::json& scene_fingerprint,
                                 const std::filesystem::path& refs_dir, int threads,
                                 const ReferenceStore* store, ReferenceSource* source,
                                 std::FILE* notes) {
  const std::string stem = reference_stem(resolved, scene_fingerprint);
  const std::filesystem::path image_path = refs_dir / (stem + ".png");
  const std::filesystem::path mask_path = refs_dir / reference_mask_path(stem + ".png");
  const std::filesystem::path marker = refs_dir / (stem + ".json");
  const nlohmann::json marker_content = reference_marker(resolved, scene_fingerprint);
  const auto found = [&](ReferenceSource s) {
    if (source) *source = s;
  };

  // Processes sharing the directory (sweep shards) take turns: the first renders and writes
  // the reference, the others wait and then load it, so it is rendered once and never
  // written by two processes at a time.
  std::filesystem::create_directories(refs_dir);
  const io::FileLock lock(refs_dir / (stem + ".lock"), [&] {
    if (notes) {
      fmt::print(notes, "waiting for another process rendering {}\n", image_path.string());
    }
  });
  const auto note = [&](const std::string& where, const KeptReference& kept) {
    if (notes && !kept.discarded.empty()) {
      fmt::print(notes, "note: discarded the reference kept in {}: {}\n", where, kept.discarded);
    }
  };
  KeptReference kept = load_marked_reference(marker, marker_content, resolved.width,
                                             resolved.height, image_path, mask_path);
  note(refs_dir.string(), kept);
  if (kept.images) {
    found(ReferenceSource::kKept);
    return std::move(*kept.images);
  }
  ReferenceImages images;
  KeptReference stored;
  if (store) {
    stored = store->load(marker_content, resolved.width, resolved.height);
    note("the reference store " + store->dir().string(), stored);
  }
  if (stored.images) {
    images = std::move(*stored.images);
    found(ReferenceSource::kStore);
    if (notes) {
      fmt::print(notes, "reference {}x{}: reused from the reference store {}\n", resolved.width,
                 resolved.height, store->dir().string());
    }
  } else {
    // The reference takes seconds to minutes at full resolution: say so, or the sweep looks
    // hung.
    if (notes) {
      fmt::print(notes, "rendering the reference {}x{} (cached in {} for later runs) ...\n",
                 resolved.width, resolved.height, refs_dir.string());
    }
    const auto start = std::chrono::steady_clock::now();
    images = reference_images(pipeline::render_reference(scene, resolved, threads));
    if (notes) {
      fmt::print(notes, "reference {}x{} rendered in {:.1f} s\n", resolved.width, resolved.height,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    found(ReferenceSource::kRendered);
  }
  save_marked_reference(marker_content, images, marker, image_path, mask_path);
  if (store && !stored.images) {
    const std::string not_kept = store->keep(marker_content, images);
    if (notes && !not_kept.empty()) {
      fmt::print(notes, "note: the reference was not kept in the reference store {}: {}\n",
                 store->dir().string(), not_kept);
    }
  }
  return images;
}

}  // namespace skinsim::driver
