#include "tests/scene/preview_raster.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

namespace skinsim::scene::testing {
namespace {

glm::vec4 sample(const Image& img, glm::vec2 uv) {
  const float fx = uv.x - std::floor(uv.x), fy = uv.y - std::floor(uv.y);
  const int x = std::min(img.width - 1, static_cast<int>(fx * img.width));
  const int y = std::min(img.height - 1, static_cast<int>(fy * img.height));
  glm::vec4 t = img.texels[static_cast<std::size_t>(y) * img.width + x];
  if (img.srgb) t = glm::vec4(glm::pow(glm::vec3(t), glm::vec3(2.2f)), t.a);
  return t;
}

}  // namespace

PreviewFrame rasterize(const Scene& scene, int width, int height) {
  PreviewFrame f{width, height, std::vector<int>(width * height, -1),
                 std::vector<glm::vec3>(width * height, glm::vec3(0.0f))};
  std::vector<float> depth(width * height, std::numeric_limits<float>::infinity());
  const Camera& c = scene.camera;
  const glm::mat4 view = glm::lookAt(c.position, c.target, c.up);
  const glm::mat4 proj = glm::perspective(c.yfov_radians, float(width) / height, c.znear, c.zfar);
  const glm::mat4 vp = proj * view;
  for (const Mesh& m : scene.meshes) {
    const Material& mat = scene.materials[m.material];
    std::vector<glm::vec3> screen(m.positions.size());
    std::vector<bool> ok(m.positions.size());
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      const glm::vec4 clip = vp * glm::vec4(m.positions[i], 1.0f);
      ok[i] = clip.w > c.znear;
      const glm::vec3 ndc = glm::vec3(clip) / clip.w;
      screen[i] = glm::vec3((ndc.x * 0.5f + 0.5f) * width, (0.5f - ndc.y * 0.5f) * height, ndc.z);
    }
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
      const std::uint32_t i0 = m.indices[t], i1 = m.indices[t + 1], i2 = m.indices[t + 2];
      if (!ok[i0] || !ok[i1] || !ok[i2]) continue;
      const glm::vec3 a = screen[i0], b = screen[i1], d = screen[i2];
      // y points down on screen, so counter-clockwise front faces have negative area here.
      const float area = (b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x);
      if (area >= 0.0f) continue;
      const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, d.x}))));
      const int x1 = std::min(width - 1, int(std::ceil(std::max({a.x, b.x, d.x}))));
      const int y0 = std::max(0, int(std::floor(std::min({a.y, b.y, d.y}))));
      const int y1 = std::min(height - 1, int(std::ceil(std::max({a.y, b.y, d.y}))));
      for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
          const float px = x + 0.5f, py = y + 0.5f;
          const float w0 = ((b.x - px) * (d.y - py) - (b.y - py) * (d.x - px)) / area;
          const float w1 = ((d.x - px) * (a.y - py) - (d.y - py) * (a.x - px)) / area;
          const float w2 = 1.0f - w0 - w1;
          if (w0 < 0.0f || w1 < 0.0f || w2 < 0.0f) continue;
          const float z = w0 * a.z + w1 * b.z + w2 * d.z;
          const std::size_t p = static_cast<std::size_t>(y) * width + x;
          if (z >= depth[p]) continue;
          depth[p] = z;
          f.material[p] = m.material;
          // Affine (not perspective-correct) interpolation is fine for a preview.
          const glm::vec3 n =
              glm::normalize(w0 * m.normals[i0] + w1 * m.normals[i1] + w2 * m.normals[i2]);
          const glm::vec4 tg = w0 * m.tangents[i0] + w1 * m.tangents[i1] + w2 * m.tangents[i2];
          const glm::vec2 uv = w0 * m.uvs[i0] + w1 * m.uvs[i1] + w2 * m.uvs[i2];
          glm::vec3 shading_n = n;
          if (mat.normal_texture >= 0) {
            const glm::vec3 tn =
                glm::vec3(sample(scene.images[mat.normal_texture], uv)) * 2.0f - 1.0f;
            const glm::vec3 tt = glm::normalize(glm::vec3(tg) - n * glm::dot(n, glm::vec3(tg)));
            const glm::vec3 bt = glm::cross(n, tt) * (tg.w < 0.0f ? -1.0f : 1.0f);
            shading_n = glm::normalize(tt * tn.x * mat.normal_scale + bt * tn.y * mat.normal_scale +
                                       n * tn.z);
          }
          glm::vec3 albedo = glm::vec3(mat.base_color_factor);
          if (mat.base_color_texture >= 0)
            albedo *= glm::vec3(sample(scene.images[mat.base_color_texture], uv));
          const float ndl = std::max(0.0f, glm::dot(shading_n, scene.key_light.direction));
          f.color[p] = albedo * (scene.ambient + scene.key_light.radiance * ndl);
        }
      }
    }
  }
  return f;
}

double coverage(const Scene& scene, const PreviewFrame& f, MaterialKind kind) {
  std::size_t hits = 0;
  for (int m : f.material) hits += m >= 0 && scene.materials[m].kind == kind;
  return static_cast<double>(hits) / f.material.size();
}

}  // namespace skinsim::scene::testing
