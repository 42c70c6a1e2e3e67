#include "driver/reference_cache.h"

#include <exception>

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

}  // namespace skinsim::driver
