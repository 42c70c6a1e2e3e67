#include "pipeline/techniques/uv_layout.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "pipeline/config.h"

namespace skinsim::pipeline {

namespace {
bool is_skin(const GpuScene& gs, const GpuMesh& m) {
  return gs.materials()[m.material].kind == scene::MaterialKind::kSkin;
}

float cross2(glm::vec2 a, glm::vec2 b) {
  return a.x * b.y - a.y * b.x;
}

// Writes value(barycentrics) into every texel whose centre lies in the UV triangle.
template <class Value>
void rasterise_uv_triangle(const glm::vec2 (&uv)[3], int size, std::vector<float>& texels,
                           std::vector<std::uint8_t>& covered, const Value& value) {
  glm::vec2 p[3];
  for (int k = 0; k < 3; ++k) p[k] = uv[k] * static_cast<float>(size);
  const float area = cross2(p[1] - p[0], p[2] - p[0]);
  if (std::fabs(area) < 1e-12f) return;
  const int x0 = std::max(0, static_cast<int>(std::floor(std::min({p[0].x, p[1].x, p[2].x}))));
  const int y0 = std::max(0, static_cast<int>(std::floor(std::min({p[0].y, p[1].y, p[2].y}))));
  const int x1 =
      std::min(size - 1, static_cast<int>(std::ceil(std::max({p[0].x, p[1].x, p[2].x}))));
  const int y1 =
      std::min(size - 1, static_cast<int>(std::ceil(std::max({p[0].y, p[1].y, p[2].y}))));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const glm::vec2 c(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
      const float b0 = cross2(p[1] - c, p[2] - c) / area;
      const float b1 = cross2(p[2] - c, p[0] - c) / area;
      const float b2 = 1.0f - b0 - b1;
      if (b0 < 0.0f || b1 < 0.0f || b2 < 0.0f) continue;
      const std::size_t i = static_cast<std::size_t>(y) * size + x;
      texels[i] = value(b0, b1, b2);
      covered[i] = 1;
    }
  }
}

// One ring of uncovered texels takes the mean of its covered 4-neighbours.
void dilate(int size, std::vector<float>& texels, std::vector<std::uint8_t>& covered) {
  std::vector<float> out = texels;
  std::vector<std::uint8_t> out_covered = covered;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * size + x;
      if (covered[i]) continue;
      float sum = 0.0f;
      int n = 0;
      for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const int nx = x + dx, ny = y + dy;
        if (nx < 0 || ny < 0 || nx >= size || ny >= size) continue;
        const std::size_t j = static_cast<std::size_t>(ny) * size + nx;
        if (!covered[j]) continue;
        sum += texels[j];
        ++n;
      }
      if (n > 0) {
        out[i] = sum / static_cast<float>(n);
        out_covered[i] = 1;
      }
    }
  }
  texels.swap(out);
  covered.swap(out_covered);
}
}  // namespace

void require_skin_uvs(const GpuScene& gs, const char* technique) {
  for (const GpuMesh& m : gs.meshes()) {
    if (is_skin(gs, m) && m.mesh->uvs.empty()) {
      throw ConfigError(
          fmt::format("{}: skin mesh '{}' has no TEXCOORD_0; this technique works in the UV layout",
                      technique, m.mesh->name));
    }
  }
}

float uv_texels_per_mm(const GpuScene& gs, int size) {
  double surface_mm2 = 0.0, uv_area = 0.0;
  const double mm_per_unit = 1.0 / gs.scene().units_per_mm;
  for (const GpuMesh& m : gs.meshes()) {
    if (!is_skin(gs, m) || m.mesh->uvs.empty()) continue;
    const scene::Mesh& mesh = *m.mesh;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
      const glm::vec3 e1 = mesh.positions[b] - mesh.positions[a];
      const glm::vec3 e2 = mesh.positions[c] - mesh.positions[a];
      surface_mm2 += 0.5 * glm::length(glm::cross(e1, e2)) * mm_per_unit * mm_per_unit;
      uv_area += 0.5 * std::fabs(cross2(mesh.uvs[b] - mesh.uvs[a], mesh.uvs[c] - mesh.uvs[a]));
    }
  }
  if (surface_mm2 <= 0.0 || uv_area <= 0.0) return 0.0f;
  return static_cast<float>(size * std::sqrt(uv_area / surface_mm2));
}

std::vector<float> vertex_curvature(const scene::Mesh& mesh, float units_per_mm,
                                    int smoothing_passes) {
  const std::size_t n = mesh.positions.size();
  std::vector<float> sum(n, 0.0f);
  std::vector<int> count(n, 0);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(mesh.indices.size());
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = mesh.indices[t + k], b = mesh.indices[t + (k + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const auto& [a, b] : edges) {
    const float length_mm = glm::length(mesh.positions[a] - mesh.positions[b]) / units_per_mm;
    if (length_mm <= 0.0f || mesh.normals.empty()) continue;
    const float k = glm::length(mesh.normals[a] - mesh.normals[b]) / length_mm;
    sum[a] += k;
    sum[b] += k;
    ++count[a];
    ++count[b];
  }
  std::vector<float> curvature(n, 0.0f);
  for (std::size_t i = 0; i < n; ++i) {
    curvature[i] = count[i] > 0 ? sum[i] / static_cast<float>(count[i]) : 0.0f;
  }
  for (int pass = 0; pass < smoothing_passes; ++pass) {
    std::vector<float> next = curvature;  // each vertex: mean of itself and its neighbours
    std::vector<int> weight(n, 1);
    for (const auto& [a, b] : edges) {
      next[a] += curvature[b];
      next[b] += curvature[a];
      ++weight[a];
      ++weight[b];
    }
    for (std::size_t i = 0; i < n; ++i) curvature[i] = next[i] / static_cast<float>(weight[i]);
  }
  return curvature;
}

sim::Texture2D vertex_value_texture(const GpuScene& gs, const char* name, int size,
                                    const VertexValues& values, float full_scale) {
  std::vector<float> texels(static_cast<std::size_t>(size) * size, 0.0f);
  std::vector<std::uint8_t> covered(texels.size(), 0);
  for (const GpuMesh& m : gs.meshes()) {
    if (!is_skin(gs, m) || m.mesh->uvs.empty()) continue;
    const scene::Mesh& mesh = *m.mesh;
    const std::vector<float> k = values(mesh);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
      const glm::vec2 uv[3] = {mesh.uvs[i0], mesh.uvs[i1], mesh.uvs[i2]};
      rasterise_uv_triangle(uv, size, texels, covered, [&](float b0, float b1, float b2) {
        return b0 * k[i0] + b1 * k[i1] + b2 * k[i2];
      });
    }
  }
  for (int ring = 0; ring < 2; ++ring) dilate(size, texels, covered);
  std::vector<glm::vec4> rgba(texels.size());
  for (std::size_t i = 0; i < texels.size(); ++i) {
    rgba[i] = glm::vec4(std::min(1.0f, texels[i] / full_scale), 0.0f, 0.0f, 1.0f);
  }
  return sim::Texture2D(name, size, size, rgba, sim::TexelFormat::kRGBA8,
                        {sim::Filter::kBilinear, sim::Wrap::kClamp}, false);
}

sim::Texture2D curvature_texture(const GpuScene& gs, int size, float max_curvature_per_mm) {
  return vertex_value_texture(
      gs, "curvature", size,
      [&](const scene::Mesh& mesh) { return vertex_curvature(mesh, gs.scene().units_per_mm, 4); },
      max_curvature_per_mm);
}

}  // namespace skinsim::pipeline
