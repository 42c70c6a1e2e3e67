#include "scene/skin_albedo.h"

#include <fmt/format.h>
#include <stb/stb_image.h>

#include <memory>
#include <optional>
#include <string_view>

#include "io/read_file.h"
#include "scene/error.h"
#include "scene/gltf_materials.h"
#include "util/parse_number.h"
#include "util/srgb.h"

namespace skinsim::scene {
namespace {

// `text` without the spaces and tabs around it.
std::string_view trimmed(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// "r,g,b" with each in [0, 255]; nullopt when `spec` does not look like three numbers (then it
// names an image). Plain string handling rather than std::regex: GCC 12 reports false
// -Wmaybe-uninitialized warnings inside <regex> under the sanitizers (io/temp_files.cpp).
std::optional<glm::vec3> parse_colour(const std::string& spec) {
  std::string_view parts[3];
  std::string_view rest = spec;
  for (int i = 0; i < 3; ++i) {
    const std::size_t comma = i < 2 ? rest.find(',') : rest.size();
    if (comma == std::string_view::npos) return std::nullopt;
    parts[i] = trimmed(rest.substr(0, comma));
    if (parts[i].empty() ||
        parts[i].find_first_not_of("+-0123456789.eE") != std::string_view::npos) {
      return std::nullopt;
    }
    rest.remove_prefix(i < 2 ? comma + 1 : comma);
  }
  glm::vec3 c;
  for (int i = 0; i < 3; ++i) {
    const std::optional<double> v = parse_real(parts[i]);
    if (!v || !(*v >= 0.0 && *v <= 255.0)) {
      throw SceneError(fmt::format(
          "--skin-albedo '{}': each of r,g,b must be a number from 0 to 255 (sRGB)", spec));
    }
    c[i] = static_cast<float>(*v);
  }
  return c;
}

Image load_albedo_image(const std::string& path) {
  // Twice the largest decoded image's bytes: an encoded image is smaller than that.
  const std::string file = io::read_regular_file(
      path, "--skin-albedo image", 2ull * gltf::kMaxImageSide * gltf::kMaxImageSide * 4);
  const auto* bytes = reinterpret_cast<const stbi_uc*>(file.data());
  const int size = static_cast<int>(file.size());
  int w = 0, h = 0, n = 0;
  if (!stbi_info_from_memory(bytes, size, &w, &h, &n)) {
    throw SceneError(fmt::format(
        "--skin-albedo '{}': neither a colour r,g,b (0-255) nor an image skinsim can read ({})",
        path, stbi_failure_reason()));
  }
  if (w > gltf::kMaxImageSide || h > gltf::kMaxImageSide) {
    throw SceneError(fmt::format("--skin-albedo '{}': {} x {} pixels is larger than {} x {}", path,
                                 w, h, gltf::kMaxImageSide, gltf::kMaxImageSide));
  }
  std::unique_ptr<stbi_uc, decltype(&stbi_image_free)> pixels(
      stbi_load_from_memory(bytes, size, &w, &h, &n, 4), stbi_image_free);
  if (!pixels) {
    throw SceneError(
        fmt::format("--skin-albedo '{}': cannot decode: {}", path, stbi_failure_reason()));
  }
  Image image;
  image.name = path;
  image.width = w;
  image.height = h;
  image.srgb = true;
  image.texels.resize(static_cast<std::size_t>(w) * h);
  for (std::size_t i = 0; i < image.texels.size(); ++i) {
    const stbi_uc* p = pixels.get() + 4 * i;
    image.texels[i] = glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
  }
  return image;
}

}  // namespace

void apply_skin_albedo(Scene& scene, const std::string& spec) {
  bool any_skin = false;
  for (const Material& m : scene.materials) any_skin = any_skin || m.kind == MaterialKind::kSkin;
  if (!any_skin) {
    throw SceneError(fmt::format(
        "--skin-albedo: {} has no skin material to colour (see --skin-materials)", scene.source));
  }
  const std::optional<glm::vec3> colour = parse_colour(spec);
  int texture = -1;
  if (!colour) {
    scene.images.push_back(load_albedo_image(spec));
    texture = static_cast<int>(scene.images.size()) - 1;
  }
  for (Material& m : scene.materials) {
    if (m.kind != MaterialKind::kSkin) continue;
    m.base_color_texture = texture;
    const glm::vec3 c = colour ? *colour / 255.0f : glm::vec3(1.0f);
    m.base_color_factor =
        glm::vec4(srgb_decode(c.r), srgb_decode(c.g), srgb_decode(c.b), m.base_color_factor.a);
  }
}

}  // namespace skinsim::scene
