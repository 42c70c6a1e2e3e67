#include "scene/gltf_primitive.h"

#include <fmt/format.h>
#include <tiny_gltf.h>

#include <cmath>
#include <utility>

#include "scene/error.h"
#include "scene/gltf_accessor.h"
#include "scene/mesh_attributes.h"
#include "util/check.h"

namespace skinsim::scene::gltf {
namespace {

template <typename Vec, int N>
std::vector<Vec> to_vectors(const std::vector<float>& flat) {
  std::vector<Vec> out(flat.size() / N);
  for (std::size_t i = 0; i < out.size(); ++i) {
    for (int c = 0; c < N; ++c) out[i][c] = flat[i * N + c];
  }
  return out;
}

bool finite3(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Triangle lists from the three triangle topologies (glTF 2.0 spec 3.7.2.1).
std::vector<std::uint32_t> to_triangle_list(std::vector<std::uint32_t> idx, int mode,
                                            const std::string& file, const std::string& where) {
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    if (idx.size() % 3 != 0) {
      throw SceneError(fmt::format("{}: {}: TRIANGLES with {} indices (not a multiple of 3)", file,
                                   where, idx.size()));
    }
    return idx;
  }
  if (idx.size() < 3) {
    throw SceneError(fmt::format("{}: {}: fewer than 3 vertices", file, where));
  }
  std::vector<std::uint32_t> list;
  list.reserve((idx.size() - 2) * 3);
  for (std::size_t i = 2; i < idx.size(); ++i) {
    if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
      list.insert(list.end(), {idx[0], idx[i - 1], idx[i]});
    } else if (i % 2 == 0) {  // strip: keep every triangle counter-clockwise
      list.insert(list.end(), {idx[i - 2], idx[i - 1], idx[i]});
    } else {
      list.insert(list.end(), {idx[i - 1], idx[i - 2], idx[i]});
    }
  }
  return list;
}

// Planar UVs over the x/y extent, v down like glTF; used when TEXCOORD_0 is missing.
std::vector<glm::vec2> planar_uvs(const std::vector<glm::vec3>& p) {
  glm::vec2 lo(INFINITY), hi(-INFINITY);
  for (const auto& q : p) {
    lo = glm::min(lo, glm::vec2(q));
    hi = glm::max(hi, glm::vec2(q));
  }
  const glm::vec2 size = glm::max(hi - lo, glm::vec2(1e-30f));
  std::vector<glm::vec2> uv(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    uv[i] = glm::vec2((p[i].x - lo.x) / size.x, 1.0f - (p[i].y - lo.y) / size.y);
  }
  return uv;
}

// One primitive being read: where its data is and how errors name it.
struct PrimitiveSource {
  const tinygltf::Model& model;
  const tinygltf::Primitive& prim;
  const std::string& file;
  std::string where;  // "meshes[m].primitives[p]"

  // The accessor of attribute `name`, or -1.
  int attribute(const char* name) const {
    auto it = prim.attributes.find(name);
    return it == prim.attributes.end() ? -1 : it->second;
  }
  // Attribute `name` (accessor `acc`), which must have one element per vertex of `n`.
  std::vector<float> read_matching(int acc, int comps, AttributeFormat format, const char* name,
                                   std::size_t n) const {
    std::vector<float> v =
        read_floats(model, acc, comps, format, file, where + ".attributes." + name);
    if (v.size() != n * comps) {
      throw SceneError(fmt::format("{}: {}.attributes.{}: {} elements, POSITION has {}", file,
                                   where, name, v.size() / comps, n));
    }
    return v;
  }
};

// The primitive's morph targets' displacements summed with their weights, per vertex; empty
// for an attribute no target displaces (or the mesh has no targets).
struct Morph {
  std::vector<glm::vec3> position, normal, tangent;
};

Morph read_morph(const PrimitiveSource& src, const std::vector<float>& weights, std::size_t n,
                 const std::function<void(const std::string&)>& warn) {
  Morph morph;
  for (std::size_t t = 0; t < src.prim.targets.size(); ++t) {
    for (const auto& [name, acc] : src.prim.targets[t]) {
      std::vector<glm::vec3>* sum = name == "POSITION"  ? &morph.position
                                    : name == "NORMAL"  ? &morph.normal
                                    : name == "TANGENT" ? &morph.tangent
                                                        : nullptr;
      const std::string where = fmt::format("{}.targets[{}].{}", src.where, t, name);
      if (!sum) {  // TEXCOORD_n and COLOR_n (spec 3.7.2.2): skinsim morphs the shape only
        warn(fmt::format("{}: {}: not morphed (only POSITION, NORMAL and TANGENT are)", src.file,
                         where));
        continue;
      }
      const std::vector<float> d =
          read_floats(src.model, acc, 3, AttributeFormat::kFloatOnly, src.file, where);
      if (d.size() != 3 * n) {
        throw SceneError(
            fmt::format("{}: {}: {} elements, POSITION has {}", src.file, where, d.size() / 3, n));
      }
      if (sum->empty()) sum->assign(n, glm::vec3(0.0f));
      for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 displacement(d[3 * i], d[3 * i + 1], d[3 * i + 2]);
        if (!finite3(displacement)) {
          throw SceneError(fmt::format("{}: {}: element {} is not finite", src.file, where, i));
        }
        (*sum)[i] += weights[t] * displacement;
      }
    }
  }
  return morph;
}

// Why the primitive is skipped (points or lines, a transform a float cannot hold or a
// singular one), or empty if it is drawn.
std::string reason_to_skip(int mode, float det) {
  if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
      mode != TINYGLTF_MODE_TRIANGLE_FAN) {
    return fmt::format("mode {} draws points or lines", mode);
  }
  if (!std::isfinite(det)) {
    return fmt::format("node transform scales by more than a float holds (determinant {})", det);
  }
  if (std::abs(det) < 1e-30f) return "node transform is singular (zero scale)";
  return {};
}

std::vector<glm::vec3> read_positions(const PrimitiveSource& src) {
  const int acc = src.attribute("POSITION");
  if (acc < 0) throw SceneError(fmt::format("{}: {}: no POSITION attribute", src.file, src.where));
  std::vector<glm::vec3> positions =
      to_vectors<glm::vec3, 3>(read_floats(src.model, acc, 3, AttributeFormat::kFloatOnly, src.file,
                                           src.where + ".attributes.POSITION"));
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!finite3(positions[i])) {
      throw SceneError(fmt::format("{}: {}.attributes.POSITION: vertex {} is not finite (NaN/Inf)",
                                   src.file, src.where, i));
    }
  }
  return positions;
}

// The primitive's triangles as a list of indices into its `n` vertices.
std::vector<std::uint32_t> read_triangles(const PrimitiveSource& src, int mode, std::size_t n) {
  std::vector<std::uint32_t> idx;
  if (src.prim.indices >= 0) {
    idx = read_indices(src.model, src.prim.indices, src.file, src.where + ".indices");
    for (std::size_t i = 0; i < idx.size(); ++i) {
      if (idx[i] >= n) {
        throw SceneError(fmt::format("{}: {}.indices: index {} (at {}) out of range of {} vertices",
                                     src.file, src.where, idx[i], i, n));
      }
    }
  } else {
    idx.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) idx[i] = i;
  }
  return to_triangle_list(std::move(idx), mode, src.file, src.where);
}

// Positions to world space; a mirroring transform (det < 0) flips the winding back to
// counter-clockwise.
void place_in_world(Mesh& m, const glm::mat4& world, float det, const PrimitiveSource& src) {
  for (auto& p : m.positions) {
    p = glm::vec3(world * glm::vec4(p, 1.0f));
    if (!finite3(p)) {
      throw SceneError(fmt::format("{}: {}: a position overflows under the node transform",
                                   src.file, src.where));
    }
  }
  if (det < 0.0f) {
    for (std::size_t t = 0; t < m.indices.size(); t += 3)
      std::swap(m.indices[t + 1], m.indices[t + 2]);
  }
}

// World-space normals: NORMAL through the inverse transpose, smooth normals where it is
// missing, zero or not finite.
void fill_normals(Mesh& m, const glm::mat3& linear, const std::vector<glm::vec3>& morph,
                  const PrimitiveSource& src, const std::function<void(const std::string&)>& warn) {
  const std::size_t n = m.positions.size();
  std::vector<glm::vec3> generated;  // smooth normals, computed only if needed
  const auto smooth = [&]() -> const std::vector<glm::vec3>& {
    if (generated.empty()) generated = compute_smooth_normals(m.positions, m.indices);
    return generated;
  };
  const int acc = src.attribute("NORMAL");
  if (acc < 0) {
    m.normals = smooth();
    return;
  }
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(linear));
  m.normals =
      to_vectors<glm::vec3, 3>(src.read_matching(acc, 3, AttributeFormat::kFloatOnly, "NORMAL", n));
  for (std::size_t i = 0; i < morph.size(); ++i) m.normals[i] += morph[i];
  std::size_t repaired = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const glm::vec3 w = normal_matrix * m.normals[i];
    const float len = glm::length(w);
    if (len > 1e-20f && std::isfinite(len)) {
      m.normals[i] = w / len;
    } else {
      m.normals[i] = smooth()[i];
      ++repaired;
    }
  }
  if (repaired > 0) {
    warn(
        fmt::format("{}: {}.attributes.NORMAL: {} zero or non-finite normals replaced by smooth "
                    "normals",
                    src.file, src.where, repaired));
  }
}

// TEXCOORD_0, or planar UVs where it is missing.
void fill_uvs(Mesh& m, const PrimitiveSource& src) {
  const std::size_t n = m.positions.size();
  const int acc = src.attribute("TEXCOORD_0");
  if (acc < 0) {
    m.uvs = planar_uvs(m.positions);
    return;
  }
  m.uvs = to_vectors<glm::vec2, 2>(
      src.read_matching(acc, 2, AttributeFormat::kFloatOrNormalized, "TEXCOORD_0", n));
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(m.uvs[i].x) || !std::isfinite(m.uvs[i].y)) {
      throw SceneError(fmt::format("{}: {}.attributes.TEXCOORD_0: element {} is not finite",
                                   src.file, src.where, i));
    }
  }
}

// World-space tangents: TANGENT transformed and made orthogonal to the normal (the
// bitangent sign flipped by a mirroring transform), or computed from the UVs.
void fill_tangents(Mesh& m, const glm::mat3& linear, float det, const std::vector<glm::vec3>& morph,
                   const PrimitiveSource& src) {
  const std::size_t n = m.positions.size();
  const int acc = src.attribute("TANGENT");
  if (acc < 0) {
    m.tangents = compute_tangents(m.positions, m.normals, m.uvs, m.indices);
    return;
  }
  m.tangents = to_vectors<glm::vec4, 4>(
      src.read_matching(acc, 4, AttributeFormat::kFloatOnly, "TANGENT", n));
  for (std::size_t i = 0; i < morph.size(); ++i) m.tangents[i] += glm::vec4(morph[i], 0.0f);
  const float flip = det < 0.0f ? -1.0f : 1.0f;
  for (std::size_t i = 0; i < n; ++i) {
    const glm::vec3& nrm = m.normals[i];
    glm::vec3 t = linear * glm::vec3(m.tangents[i]);
    t -= nrm * glm::dot(nrm, t);
    const float len = glm::length(t);
    t = len > 1e-20f && std::isfinite(len) ? t / len : any_orthogonal(nrm);
    const float w = m.tangents[i].w < 0.0f ? -1.0f : 1.0f;
    m.tangents[i] = glm::vec4(t, w * flip);
  }
}

}  // namespace

std::optional<Mesh> convert_primitive(const tinygltf::Model& model, int mesh_index, int prim_index,
                                      const glm::mat4& world, const std::vector<float>& weights,
                                      int material, const std::string& file,
                                      const std::function<void(const std::string&)>& warn) {
  const tinygltf::Mesh& src_mesh = model.meshes[static_cast<std::size_t>(mesh_index)];
  const PrimitiveSource src{model, src_mesh.primitives[static_cast<std::size_t>(prim_index)], file,
                            fmt::format("meshes[{}].primitives[{}]", mesh_index, prim_index)};
  const int mode = src.prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : src.prim.mode;
  const glm::mat3 linear(world);
  const float det = glm::determinant(linear);
  if (const std::string why = reason_to_skip(mode, det); !why.empty()) {
    warn(fmt::format("{}: {}: {}; skipped", file, src.where, why));
    return std::nullopt;
  }

  Mesh m;
  m.name = src_mesh.name.empty() ? fmt::format("mesh{}", mesh_index) : src_mesh.name;
  if (src_mesh.primitives.size() > 1) m.name += fmt::format("/{}", prim_index);
  m.material = material;
  m.positions = read_positions(src);
  SKINSIM_CHECK_OP(weights.size(), ==, src.prim.targets.size());
  const Morph morph = read_morph(src, weights, m.positions.size(), warn);
  for (std::size_t i = 0; i < morph.position.size(); ++i) m.positions[i] += morph.position[i];
  m.indices = read_triangles(src, mode, m.positions.size());
  if (m.indices.empty()) {
    warn(fmt::format("{}: {}: no triangles; skipped", file, src.where));
    return std::nullopt;
  }
  place_in_world(m, world, det, src);
  fill_normals(m, linear, morph.normal, src, warn);
  fill_uvs(m, src);
  fill_tangents(m, linear, det, morph.tangent, src);
  return m;
}

std::size_t morph_target_count(const tinygltf::Model& model, int mesh, const std::string& file) {
  const auto& primitives = model.meshes.at(static_cast<std::size_t>(mesh)).primitives;
  const std::size_t count = primitives.empty() ? 0 : primitives[0].targets.size();
  for (std::size_t p = 1; p < primitives.size(); ++p) {
    if (primitives[p].targets.size() != count) {
      throw SceneError(fmt::format(
          "{}: meshes[{}].primitives[{}].targets: {} morph targets, primitives[0] has {} (all "
          "primitives of a mesh need the same number)",
          file, mesh, p, primitives[p].targets.size(), count));
    }
  }
  return count;
}

}  // namespace skinsim::scene::gltf
