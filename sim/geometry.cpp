#include "sim/geometry.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "sim/sample_pattern.h"

namespace skinsim::sim {

namespace {

// Triangles per set-up task: large enough to amortise a task, small enough to balance.
constexpr std::size_t kTrianglesPerChunk = 4096;

struct ClipVertex {
  glm::vec4 position;
  float varyings[kMaxVaryings];
};

// Clip-space near plane (OpenGL: z >= -w). Also keeps w strictly positive.
float near_distance(const glm::vec4& p) {
  return p.z + p.w;
}

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

// Why triangles of one chunk were dropped or split.
struct SetupCounts {
  std::uint64_t culled_backface = 0;
  std::uint64_t culled_frustum = 0;
  std::uint64_t culled_degenerate = 0;
  std::uint64_t clipped = 0;
};

// The set-up of a run of consecutive triangles of one draw; varying offsets are local to it.
struct SetupChunk {
  SetupTriangles setup;
  SetupCounts counts;
};

class TriangleBuilder {
 public:
  TriangleBuilder(const RenderPassDesc& pass, const PixelRect& area, SetupChunk& out)
      : width_(pass_target(pass).width),
        height_(pass_target(pass).height),
        area_(area),
        reach_(sample_pattern(pass.samples).reach),
        out_(out.setup),
        counts_(out.counts) {}

  // Emits the set-up of one clipped (w > 0) triangle, or counts why it was dropped.
  void emit(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, int varying_count,
            CullMode cull, std::uint32_t draw) {
    std::array<ScreenVertex, 3> v = {to_screen(a), to_screen(b), to_screen(c)};
    std::int64_t area2 =
        (v[1].fx - v[0].fx) * (v[2].fy - v[0].fy) - (v[2].fx - v[0].fx) * (v[1].fy - v[0].fy);
    if (area2 == 0) {
      ++counts_.culled_degenerate;
      return;
    }
    // Screen y points down, so a counter-clockwise (front-facing, GL) triangle has area2 < 0.
    const bool front = area2 < 0;
    if ((cull == CullMode::kBack && !front) || (cull == CullMode::kFront && front)) {
      ++counts_.culled_backface;
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
    // Pixels with a sample (centre px * one + one/2, give or take the pattern's reach)
    // inside the bounding box.
    const std::int64_t half = kSubpixelOne / 2;
    auto first_pixel = [&](std::int64_t lo) {
      return static_cast<int>((lo - half - reach_ + kSubpixelOne - 1) >> kSubpixelBits);
    };
    auto last_pixel = [&](std::int64_t hi) {
      return static_cast<int>((hi - half + reach_) >> kSubpixelBits);
    };
    t.min_x = std::max(first_pixel(min_fx), area_.x0);
    t.min_y = std::max(first_pixel(min_fy), area_.y0);
    t.max_x = std::min(last_pixel(max_fx), area_.x1 - 1);
    t.max_y = std::min(last_pixel(max_fy), area_.y1 - 1);
    if (t.min_x > t.max_x || t.min_y > t.max_y) {
      ++counts_.culled_degenerate;  // covers no sample in the render area
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
  std::int64_t reach_;  // of the pass's sample pattern
  SetupTriangles& out_;
  SetupCounts& counts_;
};

// Sets up triangles [first, last) of a draw whose vertices are shaded.
void set_up_triangles(const RenderPassDesc& pass, const PixelRect& area, std::uint32_t d,
                      const std::vector<ExecVertexOut>& shaded, std::size_t first, std::size_t last,
                      SetupChunk& out) {
  const DrawCall& draw = pass.draws[d];
  const Geometry& g = draw.geometry;
  const int varying_count = draw.vertex_program->varying_floats();
  TriangleBuilder builder(pass, area, out);
  for (std::size_t tri = first; tri < last; ++tri) {
    const std::size_t i = 3 * tri;
    std::array<ClipVertex, 3> v;
    for (int k = 0; k < 3; ++k) {
      const ExecVertexOut& s = shaded[g.indices[i + k]];
      v[k].position = s.position;
      std::copy(s.varyings, s.varyings + varying_count, v[k].varyings);
    }
    if (outside_same_plane(v[0].position, v[1].position, v[2].position)) {
      ++out.counts.culled_frustum;
      continue;
    }
    const bool needs_clip = near_distance(v[0].position) < 0.0f ||
                            near_distance(v[1].position) < 0.0f ||
                            near_distance(v[2].position) < 0.0f;
    if (!needs_clip) {
      builder.emit(v[0], v[1], v[2], varying_count, draw.cull, d);
      continue;
    }
    ++out.counts.clipped;
    std::array<ClipVertex, 4> poly;
    const int n = clip_near(v, poly, varying_count);
    for (int k = 1; k + 1 < n; ++k) {
      builder.emit(poly[0], poly[k], poly[k + 1], varying_count, draw.cull, d);
    }
  }
}

// Appends the chunks in order, rebasing their varying offsets, and adds up their counts.
// Each chunk copies into its own slice, so the copies run in parallel.
void join_chunks(const std::vector<SetupChunk>& chunks, SetupTriangles& out,
                 PassCounters& counters) {
  std::vector<std::size_t> triangle_at(chunks.size() + 1, out.triangles.size());
  std::vector<std::size_t> plane_at(chunks.size() + 1, out.varying_planes.size());
  for (std::size_t k = 0; k < chunks.size(); ++k) {
    const SetupChunk& c = chunks[k];
    triangle_at[k + 1] = triangle_at[k] + c.setup.triangles.size();
    plane_at[k + 1] = plane_at[k] + c.setup.varying_planes.size();
    counters.triangles_culled_backface += c.counts.culled_backface;
    counters.triangles_culled_frustum += c.counts.culled_frustum;
    counters.triangles_culled_degenerate += c.counts.culled_degenerate;
    counters.triangles_clipped += c.counts.clipped;
  }
  out.triangles.resize(triangle_at.back());
  out.varying_planes.resize(plane_at.back());
  tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t k) {
    const SetupTriangles& c = chunks[k].setup;
    const auto rebase = static_cast<std::uint32_t>(plane_at[k]);
    std::transform(c.triangles.begin(), c.triangles.end(), out.triangles.begin() + triangle_at[k],
                   [rebase](TriangleSetup t) {
                     t.varying_offset += rebase;
                     return t;
                   });
    std::copy(c.varying_planes.begin(), c.varying_planes.end(),
              out.varying_planes.begin() + plane_at[k]);
  });
}

}  // namespace

PixelRect tile_aligned_area(const RenderPassDesc& pass, int tile_size) {
  const int w = pass_target(pass).width, h = pass_target(pass).height;
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

    // Set-up in fixed chunks of triangles, joined in submission order: the result does not
    // depend on how many threads run the chunks.
    const std::size_t triangles = g.index_count / 3;
    std::vector<SetupChunk> chunks((triangles + kTrianglesPerChunk - 1) / kTrianglesPerChunk);
    tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t k) {
      set_up_triangles(pass, area, d, shaded, k * kTrianglesPerChunk,
                       std::min(triangles, (k + 1) * kTrianglesPerChunk), chunks[k]);
    });
    join_chunks(chunks, out, counters);
  }
  counters.triangles_binned = out.triangles.size();
  return out;
}

}  // namespace skinsim::sim
