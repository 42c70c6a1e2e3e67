#include "driver/reference_cache.h"

#include <exception>

#include "io/read_file.h"
#include "pipeline/knob.h"
#include "quality/image.h"
#include "util/build_identity.h"

namespace skinsim::driver {

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
  return std::filesystem::path(reference_image).replace_extension().string() + "_skin.png";
}

bool load_reference(const std::filesystem::path& image, const std::filesystem::path& mask,
                    ReferenceImages& out) {
  try {
    out.image = quality::load_png(image);
    out.skin = quality::load_mask_png(mask);
  } catch (const std::exception&) {
    return false;  // damaged or deleted by hand: render again
  }
  return out.image.width == out.skin.width && out.image.height == out.skin.height;
}

std::optional<ReferenceImages> load_marked_reference(const std::filesystem::path& marker,
                                                     const nlohmann::json& expected,
                                                     const std::filesystem::path& image,
                                                     const std::filesystem::path& mask) {
  try {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(marker, ec)) return std::nullopt;
    const nlohmann::json stored =
        nlohmann::json::parse(io::read_regular_file(marker, "reference cache marker"), nullptr,
                              /*allow_exceptions=*/false);
    ReferenceImages images;
    if (stored != expected || !load_reference(image, mask, images)) return std::nullopt;
    return images;
  } catch (const std::exception&) {
    return std::nullopt;  // unreadable, or removed meanwhile: render it
  }
}

}  // namespace skinsim::driver
