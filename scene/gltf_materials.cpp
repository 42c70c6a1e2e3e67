#include "scene/gltf_materials.h"

#include <fmt/format.h>
#include <stb/stb_image.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <map>
#include <utility>

#include "scene/error.h"
#include "scene/gltf_accessor.h"

namespace skinsim::scene::gltf {
namespace {

// Reads the width and height from the encoded image's header and refuses oversized images
// before stb_image allocates width * height * channels bytes for them.
bool within_size_limit(const unsigned char* bytes, int size, int index, std::string* err) {
  int width = 0, height = 0, channels = 0;
  // stb_image's own header reader refuses PNGs over 1 GiB decoded without saying why, so
  // read a PNG's IHDR (signature, length, "IHDR", big-endian width and height) directly.
  static constexpr unsigned char kPngIhdr[16] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n',
                                                 0,    0,   0,   13,  'I',  'H',  'D',  'R'};
  if (size >= 24 && std::memcmp(bytes, kPngIhdr, sizeof kPngIhdr) == 0) {
    auto big_endian = [&](int at) {
      return (std::uint32_t{bytes[at]} << 24) | (std::uint32_t{bytes[at + 1]} << 16) |
             (std::uint32_t{bytes[at + 2]} << 8) | bytes[at + 3];
    };
    const std::uint32_t w = big_endian(16), h = big_endian(20);
    width = static_cast<int>(std::min<std::uint32_t>(w, 1u << 30));
    height = static_cast<int>(std::min<std::uint32_t>(h, 1u << 30));
  } else if (!stbi_info_from_memory(bytes, size, &width, &height, &channels)) {
    return true;  // not an image stb_image knows; decoding reports it
  }
  if (width <= kMaxImageSide && height <= kMaxImageSide) return true;
  if (err) {
    *err += fmt::format("images[{}]: {} x {} pixels is larger than skinsim's limit of {} x {}",
                        index, width, height, kMaxImageSide, kMaxImageSide);
  }
  return false;
}

glm::vec4 texel(const tinygltf::Image& img, std::size_t i) {
  const int comps = img.component;
  float v[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  for (int c = 0; c < comps; ++c) {
    const std::size_t at = i * comps + c;
    if (img.bits == 16) {
      const auto lo = img.image[2 * at], hi = img.image[2 * at + 1];  // stb: native order
      v[c] = static_cast<float>(static_cast<std::uint16_t>(lo | (hi << 8))) / 65535.0f;
    } else {
      v[c] = img.image[at] / 255.0f;
    }
  }
  switch (comps) {
    case 1:
      return {v[0], v[0], v[0], 1.0f};
    case 2:
      return {v[0], v[0], v[0], v[1]};
    case 3:
      return {v[0], v[1], v[2], 1.0f};
    default:
      return {v[0], v[1], v[2], v[3]};
  }
}

Image convert_image(const tinygltf::Image& img, int index, bool srgb, const std::string& file) {
  const std::string where =
      fmt::format("images[{}] ('{}')", index, img.uri.empty() ? img.name : img.uri);
  if (img.image.empty() || img.width <= 0 || img.height <= 0) {
    throw SceneError(fmt::format("{}: {}: could not be loaded or decoded", file, where));
  }
  if (img.component < 1 || img.component > 4 || (img.bits != 8 && img.bits != 16)) {
    throw SceneError(fmt::format("{}: {}: unsupported layout ({} channels, {} bits)", file, where,
                                 img.component, img.bits));
  }
  const std::size_t count = static_cast<std::size_t>(img.width) * img.height;
  if (img.image.size() != count * img.component * (img.bits / 8)) {
    throw SceneError(fmt::format("{}: {}: decoded size does not match {}x{}", file, where,
                                 img.width, img.height));
  }
  Image out;
  out.name =
      img.name.empty() ? (img.uri.empty() ? fmt::format("image{}", index) : img.uri) : img.name;
  out.width = img.width;
  out.height = img.height;
  out.srgb = srgb;
  out.texels.resize(count);
  for (std::size_t i = 0; i < count; ++i) out.texels[i] = texel(img, i);
  return out;
}

class ImageTable {
 public:
  ImageTable(const tinygltf::Model& model, const std::string& file, Scene& scene)
      : model_(model), file_(file), scene_(scene) {}

  // Scene image index for glTF texture `texture`, or -1 if it has no image source.
  int resolve(int texture, bool srgb, const std::string& where,
              const std::function<void(const std::string&)>& warn) {
    if (texture < 0) return -1;
    if (static_cast<std::size_t>(texture) >= model_.textures.size()) {
      throw SceneError(fmt::format("{}: {}: texture index {} out of range ({} textures)", file_,
                                   where, texture, model_.textures.size()));
    }
    const int source = model_.textures[static_cast<std::size_t>(texture)].source;
    if (source < 0) {
      warn(fmt::format("{}: {}: textures[{}] has no image source that skinsim can read; ignored",
                       file_, where, texture));
      return -1;
    }
    if (static_cast<std::size_t>(source) >= model_.images.size()) {
      throw SceneError(fmt::format("{}: textures[{}].source {} out of range ({} images)", file_,
                                   texture, source, model_.images.size()));
    }
    const auto key = std::make_pair(source, srgb);
    if (auto it = done_.find(key); it != done_.end()) return it->second;
    const tinygltf::Image* img = &model_.images[static_cast<std::size_t>(source)];
    tinygltf::Image decoded;
    if (img->image.empty() && img->bufferView >= 0) {
      decoded = *img;  // no pixels yet, so a cheap copy
      decode_from_buffer_view(decoded, source);
      img = &decoded;
    }
    scene_.images.push_back(convert_image(*img, source, srgb, file_));
    const int index = static_cast<int>(scene_.images.size()) - 1;
    done_.emplace(key, index);
    return index;
  }

 private:
  void decode_from_buffer_view(tinygltf::Image& img, int source) {
    std::size_t size = 0;
    const unsigned char* bytes = buffer_view_bytes(model_, img.bufferView, &size, file_,
                                                   fmt::format("images[{}].bufferView", source));
    if (size == 0 || size > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
      throw SceneError(
          fmt::format("{}: images[{}]: bufferView size {} is not decodable", file_, source, size));
    }
    std::string err, warn;
    if (!within_size_limit(bytes, static_cast<int>(size), source, &err) ||
        !tinygltf::LoadImageData(&img, source, &err, &warn, 0, 0, bytes, static_cast<int>(size),
                                 nullptr)) {
      throw SceneError(fmt::format("{}: images[{}]: cannot decode: {}", file_, source, err));
    }
  }

  const tinygltf::Model& model_;
  const std::string& file_;
  Scene& scene_;
  std::map<std::pair<int, bool>, int> done_;
};

std::string extras_kind(const tinygltf::Material& m, const std::string& file, int index) {
  if (!m.extras.IsObject() || !m.extras.Has("skinsim")) return {};
  const tinygltf::Value& skinsim = m.extras.Get("skinsim");
  if (!skinsim.IsObject() || !skinsim.Has("kind")) return {};
  const tinygltf::Value& kind = skinsim.Get("kind");
  const std::string value = kind.IsString() ? kind.Get<std::string>() : std::string();
  if (value != "skin" && value != "eye" && value != "other") {
    throw SceneError(
        fmt::format("{}: materials[{}].extras.skinsim.kind must be \"skin\", \"eye\" or \"other\"",
                    file, index));
  }
  return value;
}

double number_or(const tinygltf::Value& v, double fallback) {
  return v.IsNumber() || v.IsInt() ? v.GetNumberAsDouble() : fallback;
}

}  // namespace

bool decode_unless_in_buffer_view(tinygltf::Image* image, int index, std::string* err,
                                  std::string* warn, int req_width, int req_height,
                                  const unsigned char* bytes, int size, void* user_data) {
  if (image->bufferView >= 0) return true;
  if (!within_size_limit(bytes, size, index, err)) return false;
  return tinygltf::LoadImageData(image, index, err, warn, req_width, req_height, bytes, size,
                                 user_data);
}

void convert_materials(const tinygltf::Model& model, const std::string& file, Scene& scene,
                       const std::function<void(const std::string&)>& warn) {
  ImageTable images(model, file, scene);
  for (std::size_t i = 0; i < model.materials.size(); ++i) {
    const tinygltf::Material& src = model.materials[i];
    const int index = static_cast<int>(i);
    const std::string where = fmt::format("materials[{}]", i);
    const auto& pbr = src.pbrMetallicRoughness;
    Material m;
    m.name = src.name.empty() ? fmt::format("material{}", i) : src.name;
    if (pbr.baseColorFactor.size() != 4) {
      throw SceneError(
          fmt::format("{}: {}.pbrMetallicRoughness.baseColorFactor needs 4 numbers", file, where));
    }
    m.base_color_factor = glm::vec4(pbr.baseColorFactor[0], pbr.baseColorFactor[1],
                                    pbr.baseColorFactor[2], pbr.baseColorFactor[3]);
    m.metallic_factor = static_cast<float>(pbr.metallicFactor);
    m.roughness_factor = static_cast<float>(pbr.roughnessFactor);
    m.normal_scale = static_cast<float>(src.normalTexture.scale);
    for (const auto& [texture, tex_coord] :
         {std::pair{pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord},
          std::pair{pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord},
          std::pair{src.normalTexture.index, src.normalTexture.texCoord}}) {
      if (texture >= 0 && tex_coord != 0) {
        warn(fmt::format("{}: {}: texture uses TEXCOORD_{}; skinsim reads TEXCOORD_0 only", file,
                         where, tex_coord));
      }
    }
    m.base_color_texture =
        images.resolve(pbr.baseColorTexture.index, true, where + ".baseColorTexture", warn);
    m.metallic_roughness_texture = images.resolve(pbr.metallicRoughnessTexture.index, false,
                                                  where + ".metallicRoughnessTexture", warn);
    m.normal_texture =
        images.resolve(src.normalTexture.index, false, where + ".normalTexture", warn);
    if (src.occlusionTexture.index >= 0) {
      warn(
          fmt::format("{}: {}.occlusionTexture ignored: skinsim bakes ambient occlusion from the "
                      "geometry",
                      file, where));
    }
    if (auto it = src.extensions.find("KHR_materials_specular"); it != src.extensions.end()) {
      const tinygltf::Value& ext = it->second;
      if (ext.IsObject() && ext.Has("specularFactor")) {
        m.reflectivity = static_cast<float>(number_or(ext.Get("specularFactor"), 1.0));
      }
      for (const char* texture : {"specularTexture", "specularColorTexture"}) {
        if (ext.IsObject() && ext.Has(texture)) {
          warn(
              fmt::format("{}: {}.extensions.KHR_materials_specular.{} ignored: skinsim reads "
                          "the specularFactor only",
                          file, where, texture));
        }
      }
    }
    m.extras_kind = extras_kind(src, file, index);
    for (float f : {m.base_color_factor.r, m.base_color_factor.g, m.base_color_factor.b,
                    m.base_color_factor.a, m.metallic_factor, m.roughness_factor, m.normal_scale,
                    m.reflectivity}) {
      if (!std::isfinite(f)) {
        throw SceneError(fmt::format("{}: {}: a factor is not a finite number", file, where));
      }
    }
    scene.materials.push_back(std::move(m));
  }
}

}  // namespace skinsim::scene::gltf
