#include "driver/frame/reference_cache.h"

#include <fmt/format.h>

#include <exception>

#include "image/image.h"
#include "image/png_encode.h"
#include "io/atomic_file.h"
#include "io/json_input.h"
#include "pipeline/knob.h"
#include "util/build_identity.h"
#include "util/fingerprint.h"

namespace skinsim::driver {

namespace fs = std::filesystem;

namespace {

// XXH3 (64 bits) of the pixels as loaded: the 8-bit image's values are exact (k / 255), so
// the images kept and the ones loaded back from their PNGs digest alike.
std::string pixel_digest(const ReferenceImages& images) {
  const auto bytes = [](const auto& values) {
    return std::string_view(reinterpret_cast<const char*>(values.data()),
                            values.size() * sizeof(values[0]));
  };
  return xxh3_fingerprint({bytes(images.image.rgb), bytes(images.skin.values)});
}

nlohmann::json images_entry(const ReferenceImages& images) {
  return {{"width", images.image.width},
          {"height", images.image.height},
          {"pixels", pixel_digest(images)}};
}

KeptReference discarded(std::string why) {
  return {std::nullopt, std::move(why)};
}

}  // namespace

bool is_plain_file(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(fs::symlink_status(path, ec));
}

nlohmann::json reference_fingerprint(const pipeline::PipelineConfig& resolved,
                                     const nlohmann::json& scene) {
  nlohmann::json knobs = nlohmann::json::object();
  for (const pipeline::KnobSpec& k : pipeline::all_knobs()) {
    if (k.reference) knobs[k.name] = k.get(resolved);
  }
  return {{"knobs", knobs}, {"scene", scene}};
}

nlohmann::json reference_marker(const pipeline::PipelineConfig& resolved,
                                const nlohmann::json& scene) {
  return {{"fingerprint", reference_fingerprint(resolved, scene)}, {"build", build_identity()}};
}

std::string reference_mask_path(const std::string& reference_image) {
  return fs::path(reference_image).replace_extension().string() + "_skin.png";
}

nlohmann::json kept_reference_marker(const nlohmann::json& marker, const ReferenceImages& images) {
  nlohmann::json kept = marker;
  kept["images"] = images_entry(images);
  return kept;
}

KeptReference load_kept_reference(const nlohmann::json& stored, const nlohmann::json& expected,
                                  int width, int height, const fs::path& image,
                                  const fs::path& mask) {
  if (!stored.is_object()) return discarded("its marker is not a JSON object");
  nlohmann::json described = stored;
  described.erase("images");
  if (described != expected) return {};  // another build's or configuration's: no copy of this
  const nlohmann::json entry = stored.value("images", nlohmann::json());
  const auto is = [&entry](const char* key, int value) {
    return entry.is_object() && entry.contains(key) && entry[key] == value;
  };
  if (!is("width", width) || !is("height", height)) {
    return discarded(fmt::format("its marker does not describe {}x{} images", width, height));
  }
  if (!is_plain_file(image) || !is_plain_file(mask)) {
    return discarded("its images are missing, or not regular files");
  }
  ReferenceImages images;
  try {
    images.image = image::load_png(image);
    images.skin = image::load_mask_png(mask);
  } catch (const std::exception& e) {
    return discarded(e.what());
  }
  if (images_entry(images) != entry) {
    return discarded(fmt::format("its images are not the ones its marker describes ({}x{}, {})",
                                 images.image.width, images.image.height, pixel_digest(images)));
  }
  return {std::move(images), ""};
}

KeptReference load_marked_reference(const fs::path& marker, const nlohmann::json& expected,
                                    int width, int height, const fs::path& image,
                                    const fs::path& mask) {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(marker, ec);
  if (!fs::exists(status)) return {};
  nlohmann::json stored;
  try {
    stored =
        io::parse_json(io::read_own_file(marker, "reference marker"), "reference marker", marker);
  } catch (const std::exception& e) {
    return discarded(e.what());
  }
  return load_kept_reference(stored, expected, width, height, image, mask);
}

nlohmann::json save_marked_reference(const nlohmann::json& marker, const ReferenceImages& images,
                                     const fs::path& marker_file, const fs::path& image,
                                     const fs::path& mask) {
  io::replace_file_entry(image, image::encode_png(images.image, image.string()).bytes());
  io::replace_file_entry(mask, image::encode_mask_png(images.skin, mask.string()).bytes());
  nlohmann::json kept = kept_reference_marker(marker, images);
  io::replace_file_entry(marker_file, kept.dump(2) + "\n");
  return kept;
}

}  // namespace skinsim::driver
