#include "scene/validate.h"

#include <fmt/format.h>

#include <cmath>

#include "scene/error.h"

namespace skinsim::scene {
namespace {

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void check_texture(const Scene& s, const std::string& where, int texture) {
  if (texture < -1 || texture >= static_cast<int>(s.images.size())) {
    throw SceneError(fmt::format("{}: {}: texture index {} out of range (scene has {} images)",
                                 s.source, where, texture, s.images.size()));
  }
}

void validate_mesh(const Scene& s, const Mesh& m) {
  const std::string where = fmt::format("mesh '{}'", m.name);
  const std::size_t n = m.positions.size();
  if (m.normals.size() != n || m.uvs.size() != n || m.tangents.size() != n) {
    throw SceneError(fmt::format(
        "{}: {}: attribute counts differ (positions {}, normals {}, uvs {}, tangents {})", s.source,
        where, n, m.normals.size(), m.uvs.size(), m.tangents.size()));
  }
  if (m.indices.empty() || m.indices.size() % 3 != 0) {
    throw SceneError(fmt::format("{}: {}: index count {} is not a positive multiple of 3", s.source,
                                 where, m.indices.size()));
  }
  for (std::size_t i = 0; i < m.indices.size(); ++i) {
    if (m.indices[i] >= n) {
      throw SceneError(fmt::format("{}: {}: index {} (at {}) out of range of {} vertices", s.source,
                                   where, m.indices[i], i, n));
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!finite(m.positions[i])) {
      throw SceneError(fmt::format("{}: {}: position {} is not finite", s.source, where, i));
    }
    if (!finite(m.normals[i]) || !finite(glm::vec3(m.tangents[i]))) {
      throw SceneError(fmt::format("{}: {}: normal/tangent {} is not finite", s.source, where, i));
    }
  }
  if (m.material < 0 || m.material >= static_cast<int>(s.materials.size())) {
    throw SceneError(fmt::format("{}: {}: material index {} out of range ({} materials)", s.source,
                                 where, m.material, s.materials.size()));
  }
}

}  // namespace

void validate_scene(const Scene& s) {
  if (s.meshes.empty()) {
    throw SceneError(fmt::format("{}: the scene has no triangles to draw", s.source));
  }
  for (const Mesh& m : s.meshes) validate_mesh(s, m);
  for (const Material& mat : s.materials) {
    const std::string where = fmt::format("material '{}'", mat.name);
    check_texture(s, where + " base colour", mat.base_color_texture);
    check_texture(s, where + " normal", mat.normal_texture);
    check_texture(s, where + " metallic-roughness", mat.metallic_roughness_texture);
  }
  for (const Image& img : s.images) {
    if (img.width <= 0 || img.height <= 0 ||
        img.texels.size() != static_cast<std::size_t>(img.width) * img.height) {
      throw SceneError(fmt::format("{}: image '{}': {}x{} with {} texels", s.source, img.name,
                                   img.width, img.height, img.texels.size()));
    }
  }
  if (!(s.units_per_mm > 0.0f) || !std::isfinite(s.units_per_mm)) {
    throw SceneError(
        fmt::format("{}: units_per_mm must be positive, got {}", s.source, s.units_per_mm));
  }
}

}  // namespace skinsim::scene
