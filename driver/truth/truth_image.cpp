#include "driver/truth/truth_image.h"

#include <cmath>
#include <string>

#include "driver/frame/truth_process.h"
#include "util/srgb.h"
#include "util/user_error.h"

namespace skinsim::driver {

namespace {

std::string exr_tool() {
  return helper_program("SKINSIM_EXR_TOOL", "skinsim-exr");
}

void convert(const std::string& mode, const std::filesystem::path& from,
             const std::filesystem::path& to, const std::filesystem::path& log) {
  const int rc = run_program({exr_tool(), mode, from.string(), to.string()}, log);
  if (rc != 0) {
    throw UserError("skinsim-exr " + mode + " " + from.string() + " failed (exit " +
                    std::to_string(rc) + "; see " + log.string() + ")");
  }
}

}  // namespace

LinearImage read_linear_image(const std::filesystem::path& path, const std::filesystem::path& log) {
  if (!std::filesystem::is_regular_file(path)) {
    throw UserError(path.string() + ": no such image file");
  }
  const std::filesystem::path raw = log.parent_path() / (path.filename().string() + ".raw");
  convert("to-raw", path, raw, log);
  LinearImage image = read_raw_image(raw);
  std::filesystem::remove(raw);
  for (const glm::vec3& p : image.rgb) {
    if (!std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b)) {
      throw UserError(path.string() + ": holds a NaN or infinite value");
    }
  }
  return image;
}

image::Image display_image(const LinearImage& image) {
  image::Image out = image::Image::filled(image.width, image.height, glm::vec3(0.0f));
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    const glm::vec3& c = image.rgb[i];
    out.rgb[i] = {srgb_encode(c.r), srgb_encode(c.g), srgb_encode(c.b)};
  }
  image::round_to_saved_png(out);
  return out;
}

}  // namespace skinsim::driver
