#include "scene/gltf_primitive.h"

#include <fmt/format.h>
#include <tiny_gltf.h>

#include <cmath>
#include <utility>

#include "scene/error.h"
#include "scene/gltf_accessor.h"
#include "scene/mesh_attributes.h"

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

}  // namespace

std::optional<Mesh> convert_primitive(const tinygltf::Model& model, int mesh_index, int prim_index,
                                      const glm::mat4& world, int material, const std::string& file,
                                      const std::function<void(const std::string&)>& warn) {
  const tinygltf::Mesh& src_mesh = model.meshes[static_cast<std::size_t>(mesh_index)];
  const tinygltf::Primitive& prim = src_mesh.primitives[static_cast<std::size_t>(prim_index)];
  const std::string where = fmt::format("meshes[{}].primitives[{}]", mesh_index, prim_index);
  const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
  if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
      mode != TINYGLTF_MODE_TRIANGLE_FAN) {
    warn(fmt::format("{}: {}: mode {} draws points or lines; skipped", file, where, mode));
    return std::nullopt;
  }
  const glm::mat3 linear(world);
  const float det = glm::determinant(linear);
  if (!std::isfinite(det)) {
    warn(
        fmt::format("{}: {}: node transform scales by more than a float holds (determinant {}); "
                    "skipped",
                    file, where, det));
    return std::nullopt;
  }
  if (std::abs(det) < 1e-30f) {
    warn(fmt::format("{}: {}: node transform is singular (zero scale); skipped", file, where));
    return std::nullopt;
  }

  const auto attr = [&](const char* name) {
    auto it = prim.attributes.find(name);
    return it == prim.attributes.end() ? -1 : it->second;
  };
  const int pos_acc = attr("POSITION");
  if (pos_acc < 0) throw SceneError(fmt::format("{}: {}: no POSITION attribute", file, where));

  Mesh m;
  m.name = src_mesh.name.empty() ? fmt::format("mesh{}", mesh_index) : src_mesh.name;
  if (src_mesh.primitives.size() > 1) m.name += fmt::format("/{}", prim_index);
  m.material = material;
  m.positions = to_vectors<glm::vec3, 3>(read_floats(model, pos_acc, 3, AttributeFormat::kFloatOnly,
                                                     file, where + ".attributes.POSITION"));
  const std::size_t n = m.positions.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!finite3(m.positions[i])) {
      throw SceneError(fmt::format("{}: {}.attributes.POSITION: vertex {} is not finite (NaN/Inf)",
                                   file, where, i));
    }
  }
  const auto read_matching = [&](int acc, int comps, AttributeFormat format, const char* name) {
    std::vector<float> v =
        read_floats(model, acc, comps, format, file, where + ".attributes." + name);
    if (v.size() != n * comps) {
      throw SceneError(fmt::format("{}: {}.attributes.{}: {} elements, POSITION has {}", file,
                                   where, name, v.size() / comps, n));
    }
    return v;
  };

  std::vector<std::uint32_t> idx;
  if (prim.indices >= 0) {
    idx = read_indices(model, prim.indices, file, where + ".indices");
    for (std::size_t i = 0; i < idx.size(); ++i) {
      if (idx[i] >= n) {
        throw SceneError(fmt::format("{}: {}.indices: index {} (at {}) out of range of {} vertices",
                                     file, where, idx[i], i, n));
      }
    }
  } else {
    idx.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) idx[i] = i;
  }
  m.indices = to_triangle_list(std::move(idx), mode, file, where);
  if (m.indices.empty()) {
    warn(fmt::format("{}: {}: no triangles; skipped", file, where));
    return std::nullopt;
  }

  // Transform to world space. Normals use the inverse transpose; a mirroring transform
  // (det < 0) flips the winding back to counter-clockwise and the bitangent sign.
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(linear));
  for (auto& p : m.positions) {
    p = glm::vec3(world * glm::vec4(p, 1.0f));
    if (!finite3(p)) {
      throw SceneError(
          fmt::format("{}: {}: a position overflows under the node transform", file, where));
    }
  }
  if (det < 0.0f) {
    for (std::size_t t = 0; t < m.indices.size(); t += 3)
      std::swap(m.indices[t + 1], m.indices[t + 2]);
  }

  std::vector<glm::vec3> generated;  // smooth normals, computed only if needed
  const auto smooth = [&]() -> const std::vector<glm::vec3>& {
    if (generated.empty()) generated = compute_smooth_normals(m.positions, m.indices);
    return generated;
  };
  if (const int acc = attr("NORMAL"); acc >= 0) {
    m.normals =
        to_vectors<glm::vec3, 3>(read_matching(acc, 3, AttributeFormat::kFloatOnly, "NORMAL"));
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
                      file, where, repaired));
    }
  } else {
    m.normals = smooth();
  }

  if (const int acc = attr("TEXCOORD_0"); acc >= 0) {
    m.uvs = to_vectors<glm::vec2, 2>(
        read_matching(acc, 2, AttributeFormat::kFloatOrNormalized, "TEXCOORD_0"));
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(m.uvs[i].x) || !std::isfinite(m.uvs[i].y)) {
        throw SceneError(
            fmt::format("{}: {}.attributes.TEXCOORD_0: element {} is not finite", file, where, i));
      }
    }
  } else {
    m.uvs = planar_uvs(m.positions);
  }

  if (const int acc = attr("TANGENT"); acc >= 0) {
    m.tangents =
        to_vectors<glm::vec4, 4>(read_matching(acc, 4, AttributeFormat::kFloatOnly, "TANGENT"));
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
  } else {
    m.tangents = compute_tangents(m.positions, m.normals, m.uvs, m.indices);
  }
  return m;
}

}  // namespace skinsim::scene::gltf
