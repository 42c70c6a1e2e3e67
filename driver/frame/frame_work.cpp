#include "driver/frame/frame_work.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "pipeline/technique.h"
#include "util/user_error.h"

namespace skinsim::driver {

namespace {

// Pixels of a screen-space triangle inside the frame [0, width] x [0, height]: the area of
// the triangle clipped to the frame (Sutherland-Hodgman against its four edges).
double triangle_pixels(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, double width,
                       double height) {
  // A triangle clipped by four half-planes has at most 7 corners.
  std::array<glm::dvec2, 8> polygon{a, b, c}, clipped{};
  std::size_t corners = 3;
  // Each edge of the frame as "inside when dot(p, normal) <= limit".
  const std::array<std::pair<glm::dvec2, double>, 4> edges{
      {{{-1.0, 0.0}, 0.0}, {{1.0, 0.0}, width}, {{0.0, -1.0}, 0.0}, {{0.0, 1.0}, height}}};
  for (const auto& [normal, limit] : edges) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < corners; ++i) {
      const glm::dvec2 p = polygon[i], q = polygon[(i + 1) % corners];
      const double dp = glm::dot(p, normal) - limit, dq = glm::dot(q, normal) - limit;
      if (dp <= 0.0) clipped[kept++] = p;
      if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0))
        clipped[kept++] = p + (q - p) * (dp / (dp - dq));
    }
    polygon = clipped;
    corners = kept;
    if (corners == 0) return 0.0;
  }
  double twice_area = 0.0;
  for (std::size_t i = 0; i < corners; ++i) {
    const glm::dvec2 p = polygon[i], q = polygon[(i + 1) % corners];
    twice_area += p.x * q.y - q.x * p.y;
  }
  return 0.5 * std::abs(twice_area);
}

double view_fragments(const pipeline::GpuScene& scene, const pipeline::PipelineConfig& config) {
  const pipeline::View view = pipeline::make_view(scene, config);
  const double width = config.width, height = config.height;
  double fragments = 0.0;
  std::vector<glm::vec4> clip;
  for (const pipeline::GpuMesh& m : scene.meshes()) {
    const scene::Mesh& mesh = *m.mesh;
    clip.clear();
    for (const glm::vec3& p : mesh.positions) clip.push_back(view.view_proj * glm::vec4(p, 1.0f));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const glm::vec4 v[3] = {clip[mesh.indices[t]], clip[mesh.indices[t + 1]],
                              clip[mesh.indices[t + 2]]};
      if (v[0].w <= 0.0f || v[1].w <= 0.0f || v[2].w <= 0.0f) {
        fragments += width * height;  // crosses the camera's plane: may cover everything
        continue;
      }
      glm::dvec2 s[3];
      for (int i = 0; i < 3; ++i) {
        const glm::dvec2 ndc(v[i].x / v[i].w, v[i].y / v[i].w);
        s[i] = {(ndc.x * 0.5 + 0.5) * width, (0.5 - ndc.y * 0.5) * height};
      }
      // The frame's draws cull back faces: counter-clockwise is front in OpenGL's y-up
      // convention, so clockwise here, where y grows downwards.
      const double winding =
          (s[1].x - s[0].x) * (s[2].y - s[0].y) - (s[1].y - s[0].y) * (s[2].x - s[0].x);
      if (winding < 0.0) fragments += triangle_pixels(s[0], s[1], s[2], width, height);
    }
  }
  return fragments;
}

std::string frame_size(const pipeline::PipelineConfig& config) {
  return fmt::format("{}x{}", config.width, config.height);
}

}  // namespace

FrameWork estimate_frame_work(const pipeline::GpuScene& scene,
                              const pipeline::PipelineConfig& config) {
  FrameWork work;
  work.view_fragments = view_fragments(scene, config);
  work.depth_complexity = work.view_fragments / (static_cast<double>(config.width) * config.height);
  const std::vector<std::string> knobs = pipeline::technique_knobs(config.technique);
  if (std::find(knobs.begin(), knobs.end(), "texture_space_size") != knobs.end()) {
    work.texture_space_texels =
        static_cast<double>(config.texture_space.size) * config.texture_space.size;
  }
  return work;
}

void require_bounded_work(const FrameWork& work, const pipeline::PipelineConfig& config,
                          const std::string& scene_label) {
  if (work.depth_complexity <= kMaxDepthComplexity) return;
  throw UserError(fmt::format(
      "{}: its triangles cover the {} frame about {:.0f} times over ({:.2g} depth tests in the "
      "camera's pass), beyond skinsim's limit of {:.0f} (a head covers it 1-3 times): check the "
      "scene's geometry, scale and camera",
      scene_label, frame_size(config), work.depth_complexity, work.view_fragments,
      kMaxDepthComplexity));
}

std::vector<std::string> frame_work_notes(const FrameWork& work,
                                          const pipeline::PipelineConfig& config) {
  std::vector<std::string> notes;
  if (work.depth_complexity > kNotedDepthComplexity) {
    notes.push_back(fmt::format(
        "the scene's triangles cover the {} frame about {:.0f} times over ({:.2g} depth tests "
        "in the camera's pass; a head covers it 1-3 times): this frame is slow to emulate",
        frame_size(config), work.depth_complexity, work.view_fragments));
  }
  if (work.texture_space_texels > kNotedTextureSpaceTexels) {
    notes.push_back(fmt::format(
        "--texture-space-size {0}: each texture-space pass renders {0}x{0} = {1:.1f} million "
        "texels, {2:.0f} times the {3} frame's pixels: this frame takes far more time and "
        "memory than its size suggests",
        config.texture_space.size, work.texture_space_texels / 1e6,
        work.texture_space_texels / (static_cast<double>(config.width) * config.height),
        frame_size(config)));
  }
  return notes;
}

}  // namespace skinsim::driver
