// Bounds-checked reading of glTF accessors (glTF 2.0 spec, section 3.6 "Binary Data
// Storage"). tinygltf parses the JSON but does not check that an accessor fits its
// bufferView and buffer, so every byte range is validated here before it is read.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace skinsim::scene::gltf {

// Which accessor layouts a vertex attribute may use (glTF 2.0 spec, 3.7.2.1).
enum class AttributeFormat {
  kFloatOnly,          // POSITION, NORMAL, TANGENT: FLOAT
  kFloatOrNormalized,  // TEXCOORD_n: FLOAT, normalized UNSIGNED_BYTE / UNSIGNED_SHORT
};

// Reads accessor `index` as `components` floats per element (type must be SCALAR/VEC2/3/4
// with that many components). `where` names the referring field for error messages,
// e.g. "meshes[0].primitives[1].attributes.POSITION"; `file` prefixes every message.
// Sparse accessors are applied. Throws SceneError.
std::vector<float> read_floats(const tinygltf::Model& model, int index, int components,
                               AttributeFormat format, const std::string& file,
                               const std::string& where);

// Reads a SCALAR UNSIGNED_BYTE/SHORT/INT index accessor. Throws SceneError.
std::vector<std::uint32_t> read_indices(const tinygltf::Model& model, int index,
                                        const std::string& file, const std::string& where);

// Validates bufferView `view` and returns a pointer to its bytes and their count.
// Throws SceneError.
const unsigned char* buffer_view_bytes(const tinygltf::Model& model, int view, std::size_t* size,
                                       const std::string& file, const std::string& where);

}  // namespace skinsim::scene::gltf
