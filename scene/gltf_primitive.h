// Converts one glTF mesh primitive into a world-space scene::Mesh (internal to the loader).
#pragma once

#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <string>

#include "scene/scene.h"

namespace tinygltf {
class Model;
}

namespace skinsim::scene::gltf {

// Reads meshes[mesh].primitives[primitive], transforms it by `world` and fills in missing
// normals/UVs/tangents (see gltf_loader.h). Returns nullopt, after a warning, for
// primitives that draw no triangles (POINTS/LINES modes) or sit under a singular
// transform. `material` is the scene material index to use. Throws SceneError.
std::optional<Mesh> convert_primitive(const tinygltf::Model& model, int mesh, int primitive,
                                      const glm::mat4& world, int material, const std::string& file,
                                      const std::function<void(const std::string&)>& warn);

}  // namespace skinsim::scene::gltf
