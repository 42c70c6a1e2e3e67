// Converts glTF materials and the images they reference (internal to the glTF loader).
#pragma once

#include <functional>
#include <string>

#include "scene/scene.h"

namespace tinygltf {
class Model;
struct Image;
}  // namespace tinygltf

namespace skinsim::scene::gltf {

// Fills scene.materials (one per glTF material, same order) and scene.images (only the
// images a material uses; an image used both as colour and data is stored twice, with and
// without the sRGB flag). Images embedded in bufferViews are decoded here, after their
// byte range is validated. Throws SceneError naming `file` and the field at fault.
void convert_materials(const tinygltf::Model& model, const std::string& file, Scene& scene,
                       const std::function<void(const std::string&)>& warn);

// tinygltf image callback: decodes images read from files/data URIs, and leaves images in
// bufferViews undecoded (tinygltf hands those over without checking the bufferView fits
// its buffer); convert_materials() decodes them.
// Largest image side decoded (so at most 64 Mpixels, 256 MiB as 8-bit RGBA); checked from the
// image header before decoding. Skin textures are 4096 x 4096 at most in practice.
inline constexpr int kMaxImageSide = 8192;

bool decode_unless_in_buffer_view(tinygltf::Image* image, int index, std::string* err,
                                  std::string* warn, int req_width, int req_height,
                                  const unsigned char* bytes, int size, void* user_data);

}  // namespace skinsim::scene::gltf
