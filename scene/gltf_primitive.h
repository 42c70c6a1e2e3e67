// Converts one glTF mesh primitive into a world-space scene::Mesh (internal to the loader).
#pragma once

#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace tinygltf {
class Model;
}

namespace skinsim::scene::gltf {

// Reads meshes[mesh].primitives[primitive], morphs it by `weights` (one per morph target:
// each target's POSITION, NORMAL and TANGENT displacements times its weight added to the
// primitive's own, glTF 2.0 spec 3.7.2.2), transforms it by `world` and fills in missing
// normals/UVs/tangents (see gltf_loader.h). Returns nullopt, after a warning, for
// primitives that draw no triangles (POINTS/LINES modes) or sit under a singular
// transform. `material` is the scene material index to use. Throws SceneError.
std::optional<Mesh> convert_primitive(const tinygltf::Model& model, int mesh, int primitive,
                                      const glm::mat4& world, const std::vector<float>& weights,
                                      int material, const std::string& file,
                                      const std::function<void(const std::string&)>& warn);

// How many morph targets meshes[mesh] has; every primitive must have the same number (spec
// 3.7.2.2), else SceneError names the one that differs.
std::size_t morph_target_count(const tinygltf::Model& model, int mesh, const std::string& file);

}  // namespace skinsim::scene::gltf
