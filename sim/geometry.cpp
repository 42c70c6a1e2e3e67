#include "sim/geometry.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace skinsim::sim {

namespace {

struct ClipVertex {
  glm::vec4 position;
  float varyings[kMaxVaryings];
};

// Clip-space near plane (OpenGL: z >= -w). Also keeps w strictly positive.
float near_distance(const glm::vec4& p) { return p.z + p.w; }

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, float t, int varying_count) {
  ClipVertex r;
  r.position = glm::mix(a.position, b.position, t);
  for (int i = 0; i < varying_count; ++i) {
    r.varyings[i] = a.varyings[i] + (b.varyings[i] - a.varyings[i]) * t;
  }
  return r;
}

// Sutherland-Hodgman against the near plane; returns the polygon's vertex count (0, 3, 4).
int clip_near(const std::array<ClipVertex, 3>& in, std::array<ClipVertex, 4>& out,
              int varying_count) {
  int n = 0;
  for (int i = 0; i < 3; ++i) {
    const ClipVertex& a = in[i];
    const ClipVertex& b = in[(i + 1) % 3];
    const float da = near_distance(a.position), db = near_distance(b.position);
    if (da >= 0.0f) out[n++] = a;
    if ((da >= 0.0f) != (db >= 0.0f)) out[n++] = lerp(a, b, da / (da - db), varying_count);
  }
  return n;
}

bool outside_same_plane(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c) {
  for (int axis = 0; axis < 3; ++axis) {
    if (a[axis] > a.w && b[axis] > b.w && c[axis] > c.w) return true;
    if (a[axis] < -a.w && b[axis] < -b.w && c[axis] < -c.w) return true;
  }
  return false;
}

struct ScreenVertex {
  std::int64_t fx, fy;  // sub-pixel fixed point
  double x, y;          // pixels (snapped)
  double depth, inv_w;
  const float* varyings;
  double w;
};

Plane make_plane(const std::array<ScreenVertex, 3>& v, double f0, double f1, double f2,
                 double inv_area2) {
  const double x1 = v[1].x - v[0].x, y1 = v[1].y - v[0].y;
  const double x2 = v[2].x - v[0].x, y2 = v[2].y - v[0].y;
  Plane p;
  p.c = static_cast<float>(f0);
  p.dx = static_cast<float>(((f1 - f0) * y2 - (f2 - f0) * y1) * inv_area2);
  p.dy = static_cast<float>(((f2 - f0) * x1 - (f1 - f0) * x2) * inv_area2);
  return p;
}

class TriangleBuilder {
 public:
  TriangleBuilder(const RenderPassDesc& pass, const PixelRect& area, SetupTriangles& out,
                  PassCounters& counters)
      : width_(pass.color->width), height_(pass.color->height), area_(area), out_(out),
        counters_(counters) {}

  // Emits the set-up of one clipped (w > 0) triangle, or counts why it was dropped.
  void emit(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, int varying_count,
            CullMode cull, std::uint32_t draw) {
    std::array<ScreenVertex, 3> v = {to_screen(a), to_screen(b), to_screen(c)};
    std::int64_t area2 = (v[1].fx - v[0].fx) * (v[2].fy - v[0].fy) -
                         (v[2].fx - v[0].fx) * (v[1].fy - v[0].fy);
    if (area2 == 0) {
      ++counters_.triangles_culled_degenerate;
      return;
    }
    // Screen y points down, so a counter-clockwise (front-facing, GL) triangle has area2 < 0.
    const bool front = area2 < 0;
    if ((cull == CullMode::kBack && !front) || (cull == CullMode::kFront && front)) {
      ++counters_.triangles_culled_backface;
      return;
    }
    if (area2 < 0) {
      std::swap(v[1], v[2]);
      area2 = -area2;
    }
    TriangleSetup t;
    std::int64_t min_fx = v[0].fx, max_fx = v[0].fx, min_fy = v[0].fy, max_fy = v[0].fy;
    for (int i = 0; i < 3; ++i) {
      const ScreenVertex& p = v[i];
      const ScreenVertex& q = v[(i + 1) % 3];
      const std::int64_t ea = p.fy - q.fy;
      const std::int64_t eb = q.fx - p.fx;
      const bool top_left = ea > 0 || (ea == 0 && eb > 0);
      t.edge_a[i] = ea;
      t.edge_b[i] = eb;
      t.edge_c[i] = -(ea * p.fx + eb * p.fy) - (top_left ? 0 : 1);
      min_fx = std::min(min_fx, p.fx);
      max_fx = std::max(max_fx, p.fx);
      min_fy = std::min(min_fy, p.fy);
      max_fy = std::max(max_fy, p.fy);
    }
    // Pixels whose centre (px * one + one/2) lies inside the bounding box.
    const std::int64_t half = kSubpixelOne / 2;
    auto first_pixel = [&](std::int64_t lo) {
      return static_cast<int>((lo - half + kSubpixelOne - 1) >> kSubpixelBits);
    };
    auto last_pixel = [&](std::int64_t hi) { return static_cast<int>((hi - half) >> kSubpixelBits); };
    t.min_x = std::max(first_pixel(min_fx), area_.x0);
    t.min_y = std::max(first_pixel(min_fy), area_.y0);
    t.max_x = std::min(last_pixel(max_fx), area_.x1 - 1);
    t.max_y = std::min(last_pixel(max_fy), area_.y1 - 1);
    if (t.min_x > t.max_x || t.min_y > t.max_y) {
      ++counters_.triangles_culled_degenerate;  // covers no pixel centre in the render area
      return;
    }
    const double area_px = static_cast<double>(area2) / (kSubpixelOne * kSubpixelOne);
    const double inv_area2 = 1.0 / area_px;
    t.origin_x = static_cast<float>(v[0].x);
    t.origin_y = static_cast<float>(v[0].y);
    t.depth = make_plane(v, v[0].depth, v[1].depth, v[2].depth, inv_area2);
    t.inv_w = make_plane(v, v[0].inv_w, v[1].inv_w, v[2].inv_w, inv_area2);
    t.varying_offset = static_cast<std::uint32_t>(out_.varying_planes.size());
    t.draw = draw;
    for (int k = 0; k < varying_count; ++k) {
      out_.varying_planes.push_back(make_plane(v, v[0].varyings[k] * v[0].inv_w,
                                               v[1].varyings[k] * v[1].inv_w,
                                               v[2].varyings[k] * v[2].inv_w, inv_area2));
    }
    out_.triangles.push_back(t);
  }

 private:
  ScreenVertex to_screen(const ClipVertex& c) const {
    const double inv_w = 1.0 / static_cast<double>(c.position.w);
    const double nx = c.position.x * inv_w, ny = c.position.y * inv_w, nz = c.position.z * inv_w;
    const double px = (nx * 0.5 + 0.5) * width_;
    const double py = (0.5 - ny * 0.5) * height_;  // row 0 at the top
    ScreenVertex s;
    s.fx = static_cast<std::int64_t>(std::llround(px * kSubpixelOne));
    s.fy = static_cast<std::int64_t>(std::llround(py * kSubpixelOne));
    s.x = static_cast<double>(s.fx) / kSubpixelOne;
    s.y = static_cast<double>(s.fy) / kSubpixelOne;
    s.depth = std::clamp(nz * 0.5 + 0.5, 0.0, 1.0);
    s.inv_w = inv_w;
    s.varyings = c.varyings;
    s.w = c.position.w;
    return s;
  }

  int width_, height_;
  PixelRect area_;
  SetupTriangles& out_;
  PassCounters& counters_;
};

}  // namespace

PixelRect tile_aligned_area(const RenderPassDesc& pass, int tile_size) {
  const int w = pass.color->width, h = pass.color->height;
  PixelRect r{0, 0, w, h};
  if (pass.render_area) {
    const PixelRect& a = *pass.render_area;
    r.x0 = std::clamp(a.x0 / tile_size * tile_size, 0, w);
    r.y0 = std::clamp(a.y0 / tile_size * tile_size, 0, h);
    r.x1 = std::clamp((a.x1 + tile_size - 1) / tile_size * tile_size, 0, w);
    r.y1 = std::clamp((a.y1 + tile_size - 1) / tile_size * tile_size, 0, h);
  }
  return r;
}

SetupTriangles run_geometry(const RenderPassDesc& pass, const PixelRect& area,
                            PassCounters& counters) {
  SetupTriangles out;
  TriangleBuilder builder(pass, area, out, counters);
  std::vector<ExecVertexOut> shaded;
  for (std::uint32_t d = 0; d < pass.draws.size(); ++d) {
    const DrawCall& draw = pass.draws[d];
    const Geometry& g = draw.geometry;
    DrawCounters& dc = counters.draws[d];
    const int varying_count = draw.vertex_program->varying_floats();

    // Vertex shading: independent per vertex, so the parallel loop is deterministic.
    shaded.assign(g.vertex_count, ExecVertexOut{});
    const VertexProgram& vp = *draw.vertex_program;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, g.vertex_count, 4096),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i != r.end(); ++i) {
                          vp.run(ExecVertexIn(g.attributes, static_cast<std::uint32_t>(i)),
                                 shaded[i]);
                        }
                      });
    dc.vertices_shaded = g.vertex_count;
    dc.triangles_in = g.index_count / 3;
    counters.vertices_shaded += g.vertex_count;
    counters.triangles_in += g.index_count / 3;
    counters.varying_floats_per_vertex =
        std::max<std::uint64_t>(counters.varying_floats_per_vertex, varying_count);

    for (std::size_t i = 0; i + 2 < g.index_count; i += 3) {
      std::array<ClipVertex, 3> tri;
      for (int k = 0; k < 3; ++k) {
        const ExecVertexOut& s = shaded[g.indices[i + k]];
        tri[k].position = s.position;
        std::copy(s.varyings, s.varyings + varying_count, tri[k].varyings);
      }
      if (outside_same_plane(tri[0].position, tri[1].position, tri[2].position)) {
        ++counters.triangles_culled_frustum;
        continue;
      }
      const bool needs_clip = near_distance(tri[0].position) < 0.0f ||
                              near_distance(tri[1].position) < 0.0f ||
                              near_distance(tri[2].position) < 0.0f;
      if (!needs_clip) {
        builder.emit(tri[0], tri[1], tri[2], varying_count, draw.cull, d);
        continue;
      }
      ++counters.triangles_clipped;
      std::array<ClipVertex, 4> poly;
      const int n = clip_near(tri, poly, varying_count);
      for (int k = 1; k + 1 < n; ++k) {
        builder.emit(poly[0], poly[k], poly[k + 1], varying_count, draw.cull, d);
      }
    }
  }
  counters.triangles_binned = out.triangles.size();
  return out;
}

}  // namespace skinsim::sim
