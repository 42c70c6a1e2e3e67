#include "pipeline/environment_filter.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "scene/studio_lighting.h"

namespace skinsim::pipeline {

namespace {

struct Sample {
  glm::vec3 direction;
  glm::vec3 radiance_times_solid_angle;
};

// Box-downsample the source to at most 16 texels per face and keep every texel as a
// (direction, radiance x solid angle) sample.
std::vector<Sample> gather_samples(const scene::CubeMap& src) {
  const int step = std::max(1, src.size / 16);
  const int n = src.size / step;
  std::vector<Sample> samples;
  samples.reserve(static_cast<size_t>(6) * n * n);
  for (int f = 0; f < 6; ++f) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        glm::vec3 sum(0.0f);
        for (int j = 0; j < step; ++j) {
          for (int i = 0; i < step; ++i) {
            sum += glm::vec3(
                src.faces[f][static_cast<size_t>(y * step + j) * src.size + x * step + i]);
          }
        }
        const float s = 2.0f * (x + 0.5f) / n - 1.0f, t = 2.0f * (y + 0.5f) / n - 1.0f;
        const glm::vec3 d = scene::cube_face_direction(f, s, t);
        const float len = glm::length(d);
        // Solid angle of a cube texel: (texel area) / r^3 with the face at distance 1.
        const float d_omega = (2.0f / n) * (2.0f / n) / (len * len * len);
        samples.push_back({d / len, sum / float(step * step) * d_omega});
      }
    }
  }
  return samples;
}

}  // namespace

scene::CubeMap cosine_filter(const scene::CubeMap& src, int out_size) {
  const std::vector<Sample> samples = gather_samples(src);
  scene::CubeMap out;
  out.size = out_size;
  for (int f = 0; f < 6; ++f) {
    out.faces[f].resize(static_cast<size_t>(out_size) * out_size);
    tbb::parallel_for(0, out_size, [&](int y) {
      for (int x = 0; x < out_size; ++x) {
        const float s = 2.0f * (x + 0.5f) / out_size - 1.0f,
                    t = 2.0f * (y + 0.5f) / out_size - 1.0f;
        const glm::vec3 n = glm::normalize(scene::cube_face_direction(f, s, t));
        glm::vec3 e(0.0f);
        for (const Sample& smp : samples) {
          e += smp.radiance_times_solid_angle * std::max(0.0f, glm::dot(n, smp.direction));
        }
        out.faces[f][static_cast<size_t>(y) * out_size + x] = glm::vec4(e / 3.14159265f, 1.0f);
      }
    });
  }
  return out;
}

}  // namespace skinsim::pipeline
