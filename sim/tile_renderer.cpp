#include "sim/tile_renderer.h"

#include <algorithm>
#include <array>
#include <bit>

#include "util/check.h"

namespace skinsim::sim {

namespace {

glm::vec4 blend(BlendMode mode, const glm::vec4& src, const glm::vec4& dst) {
  switch (mode) {
    case BlendMode::kAlpha:
      return src * src.a + dst * (1.0f - src.a);
    case BlendMode::kAdditive:
      return src + dst;
    case BlendMode::kOpaque:
      break;
  }
  return src;
}

// Iterates the pixels of `rect` with a sample covered by triangle `t`, calling
// fn(px, py, mask, rx, ry): bit s of mask is set when sample s of `pattern` (kSamples of
// them) is covered; rx, ry are the pixel centre relative to the triangle's plane origin.
template <int kSamples, typename Fn>
void rasterize(const TriangleSetup& t, const PixelRect& rect, const SamplePattern& pattern,
               Fn&& fn) {
  const int x0 = std::max(t.min_x, rect.x0), x1 = std::min(t.max_x, rect.x1 - 1);
  const int y0 = std::max(t.min_y, rect.y0), y1 = std::min(t.max_y, rect.y1 - 1);
  if (x0 > x1 || y0 > y1) return;
  const std::int64_t half = kSubpixelOne / 2;
  const std::int64_t sx = x0 * kSubpixelOne + half, sy = y0 * kSubpixelOne + half;
  std::int64_t row[3], step_x[3], step_y[3], at_sample[3][kSamples];
  for (int e = 0; e < 3; ++e) {
    row[e] = t.edge_a[e] * sx + t.edge_b[e] * sy + t.edge_c[e];
    step_x[e] = t.edge_a[e] * kSubpixelOne;
    step_y[e] = t.edge_b[e] * kSubpixelOne;
    for (int s = 0; s < kSamples; ++s) {
      at_sample[e][s] = t.edge_a[e] * pattern.dx[s] + t.edge_b[e] * pattern.dy[s];
    }
  }
  for (int py = y0; py <= y1; ++py) {
    std::int64_t e0 = row[0], e1 = row[1], e2 = row[2];
    const float ry = static_cast<float>(py) + 0.5f - t.origin_y;
    for (int px = x0; px <= x1; ++px) {
      unsigned mask = 0;
      for (int s = 0; s < kSamples; ++s) {
        const std::int64_t inside =
            (e0 + at_sample[0][s]) | (e1 + at_sample[1][s]) | (e2 + at_sample[2][s]);
        if (inside >= 0) mask |= 1u << s;
      }
      if (mask) fn(px, py, mask, static_cast<float>(px) + 0.5f - t.origin_x, ry);
      e0 += step_x[0];
      e1 += step_x[1];
      e2 += step_x[2];
    }
    row[0] += step_y[0];
    row[1] += step_y[1];
    row[2] += step_y[2];
  }
}

}  // namespace

TileRenderer::TileRenderer(const RenderPassDesc& pass, const SetupTriangles& setup,
                           const TileGrid& grid, const GpuConfig& config)
    : pass_(pass),
      setup_(setup),
      grid_(grid),
      config_(config),
      pattern_(sample_pattern(pass.samples)),
      tex_(nullptr, nullptr),
      tex4_(tex_, config.texture_cache.line_bytes),
      inv_size_(1.0f / static_cast<float>(pass_target(pass).width),
                1.0f / static_cast<float>(pass_target(pass).height)) {
  const size_t n = static_cast<size_t>(grid.tile_size) * grid.tile_size * pattern_.count;
  color_.resize(n);
  depth_.resize(n);
  tag_.resize(n);
  if (pattern_.count > 1) resolved_.resize(static_cast<size_t>(grid.tile_size));
}

void TileRenderer::shade_batch() {
  if (batch_.empty()) return;
  const int n = static_cast<int>(batch_.size());
  // Padding lanes repeat the last fragment's inputs.
  std::array<Exec4FragIn::Fragment, sl::kLanes> fragments;
  for (int l = 0; l < sl::kLanes; ++l) {
    const Waiting& w = batch_[std::min(l, n - 1)];
    const TriangleSetup& t = setup_.triangles[w.triangle];
    const float cx = static_cast<float>(w.px) + 0.5f, cy = static_cast<float>(w.py) + 0.5f;
    fragments[l] = {setup_.varying_planes.data() + t.varying_offset,
                    &t.inv_w,
                    cx - t.origin_x,
                    cy - t.origin_y,
                    {cx, cy}};
  }
  const DrawCall& draw = pass_.draws[setup_.triangles[batch_[0].triangle].draw];
  tex_.bind(&draw.textures);
  tex4_.begin(n);
  const sl::Lanes<4> colour =
      draw.fragment_program->shade4(Exec4FragIn(fragments, inv_size_), tex4_);
  tex4_.end();
  // A fragment is shaded once, at the pixel centre, and its colour goes to every sample
  // of its pixel that the primitive covers and that passed the depth test.
  for (int l = 0; l < n; ++l) {
    glm::vec4* samples = &color_[batch_[l].index * pattern_.count];
    for (unsigned m = batch_[l].samples; m; m &= m - 1) {
      glm::vec4& dst = samples[std::countr_zero(m)];
      dst = blend(draw.blend, colour.lane(l), dst);
    }
  }
  batch_.clear();
}

void TileRenderer::queue(std::uint32_t triangle, int px, int py, std::size_t index,
                         unsigned samples) {
  SKINSIM_DCHECK_INDEX(index * pattern_.count, color_.size());
  batch_.push_back({triangle, px, py, index, samples});
  if (batch_.size() == sl::kLanes) shade_batch();
}

bool TileRenderer::flush_tags(TileCounters& counters, std::vector<std::uint64_t>& shaded) {
  const int ts = grid_.tile_size;
  const int count = pattern_.count;
  bool any = false;
  // Visible fragments are shaded four at a time, in the order they are met, a batch
  // holding fragments of one draw (one program and its textures). A pixel whose samples
  // show several triangles (an edge under MSAA) gives one fragment per triangle.
  for (int py = rect_.y0; py < rect_.y1; ++py) {
    for (int px = rect_.x0; px < rect_.x1; ++px) {
      const size_t i = static_cast<size_t>(py - rect_.y0) * ts + (px - rect_.x0);
      std::uint32_t* tags = &tag_[i * count];
      for (int s = 0; s < count; ++s) {
        const std::uint32_t tag = tags[s];
        if (tag == 0) continue;
        unsigned samples = 0;
        for (int r = s; r < count; ++r) {
          if (tags[r] != tag) continue;
          samples |= 1u << r;
          tags[r] = 0;
        }
        const std::uint32_t tri = tag - 1;
        const std::uint32_t draw = setup_.triangles[tri].draw;
        if (!batch_.empty() && setup_.triangles[batch_[0].triangle].draw != draw) shade_batch();
        queue(tri, px, py, i, samples);
        ++counters.fragments_shaded;
        ++shaded[draw];
        any = true;
      }
    }
  }
  shade_batch();
  return any;
}

template <int kSamples>
void TileRenderer::draw_triangle(std::uint32_t tri, TileCounters& counters,
                                 std::vector<std::uint64_t>& shaded,
                                 std::vector<std::uint64_t>& early_z) {
  const TriangleSetup& t = setup_.triangles[tri];
  const DrawCall& draw = pass_.draws[t.draw];
  const int ts = grid_.tile_size;
  // Hidden-surface removal applies to opaque draws that write depth: their fragments
  // only tag the pixel; shading waits until the tile's visibility is final.
  // A depth-only pass shades nothing: the ISP's depth test and write are all its work.
  const bool depth_only = !pass_.color;
  const bool deferred = draw.blend == BlendMode::kOpaque && draw.depth_write;
  if (!deferred && flush_tags(counters, shaded)) ++counters.hsr_flushes;
  // Sample offsets in pixels (exact: multiples of 1/16), for depth at each sample.
  float ox[kSamples], oy[kSamples];
  for (int s = 0; s < kSamples; ++s) {
    ox[s] = static_cast<float>(pattern_.dx[s]) / kSubpixelOne;
    oy[s] = static_cast<float>(pattern_.dy[s]) / kSubpixelOne;
  }
  rasterize<kSamples>(t, rect_, pattern_, [&](int px, int py, unsigned mask, float rx, float ry) {
    SKINSIM_DCHECK(px >= rect_.x0 && px < rect_.x1 && py >= rect_.y0 && py < rect_.y1);
    const size_t i = static_cast<size_t>(py - rect_.y0) * ts + (px - rect_.x0);
    ++counters.fragments_depth_tested;
    counters.samples_covered += static_cast<unsigned>(std::popcount(mask));
    unsigned passed = 0;
    for (unsigned m = mask; m; m &= m - 1) {
      const int s = std::countr_zero(m);
      const size_t k = i * kSamples + s;
      const float z = t.depth.at(rx + ox[s], ry + oy[s]);
      if (draw.depth_test && !(z < depth_[k])) continue;
      if (draw.depth_write) depth_[k] = z;
      passed |= 1u << s;
    }
    if (!passed || depth_only) return;
    ++early_z[t.draw];
    if (deferred) {
      for (unsigned m = passed; m; m &= m - 1) tag_[i * kSamples + std::countr_zero(m)] = tri + 1;
      return;
    }
    // Shaded in batches too: a triangle covers a pixel once, so shading its fragments
    // (and blending them over what the earlier triangles left) four at a time is shading
    // them one by one.
    queue(tri, px, py, i, passed);
    ++counters.fragments_shaded;
    ++shaded[t.draw];
    if (draw.blend != BlendMode::kOpaque) ++counters.fragments_blended;
  });
  shade_batch();
}

void TileRenderer::render(int tx, int ty, const std::vector<std::uint32_t>& triangles,
                          TileCounters& counters, TextureLineLog& lines) {
  SKINSIM_DCHECK_INDEX(tx, grid_.tiles_x);
  SKINSIM_DCHECK_INDEX(ty, grid_.tiles_y);
  rect_ = grid_.tile_rect(tx, ty);
  SKINSIM_DCHECK(rect_.x1 - rect_.x0 <= grid_.tile_size && rect_.y1 - rect_.y0 <= grid_.tile_size);
  const int ts = grid_.tile_size;
  const int count = pattern_.count;
  const int width = rect_.x1 - rect_.x0;
  const std::uint64_t pixels =
      static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(rect_.y1 - rect_.y0);
  lines.clear();
  tex_.set_tile(&counters.texture, &lines);
  counters.samples_in_tile = pixels * count;

  // Tile start: colour from a clear, or loaded from the target (costs DRAM reads) into
  // every sample of its pixel.
  std::fill(depth_.begin(), depth_.end(), 1.0f);
  std::fill(tag_.begin(), tag_.end(), 0u);
  if (pass_.color && pass_.color_load == LoadOp::kLoad) {
    for (int py = rect_.y0; py < rect_.y1; ++py) {
      glm::vec4* row = &color_[static_cast<size_t>(py - rect_.y0) * ts * count];
      for (int px = rect_.x0; px < rect_.x1; ++px) {
        std::fill_n(row + static_cast<size_t>(px - rect_.x0) * count, count,
                    pass_.color->at(px, py));
      }
    }
    counters.color_load_bytes = pixels * bytes_per_texel(pass_.color->format);
  } else {
    std::fill(color_.begin(), color_.end(), pass_.clear_color);
  }

  std::vector<std::uint64_t> shaded(pass_.draws.size(), 0);
  std::vector<std::uint64_t> early_z(pass_.draws.size(), 0);
  for (const std::uint32_t tri : triangles) {
    switch (count) {
      case 1:
        draw_triangle<1>(tri, counters, shaded, early_z);
        break;
      case 2:
        draw_triangle<2>(tri, counters, shaded, early_z);
        break;
      default:
        draw_triangle<4>(tri, counters, shaded, early_z);
        break;
    }
  }
  flush_tags(counters, shaded);

  for (std::uint32_t d = 0; d < shaded.size(); ++d) {
    if (early_z[d]) counters.shaded_by_draw.push_back({d, shaded[d], early_z[d]});
  }
  // Tile end: resolve colour to the target (under MSAA, the box average of each pixel's
  // samples, computed on chip); depth/stencil are discarded unless stored.
  if (pass_.color && pass_.store_color) {
    for (int py = rect_.y0; py < rect_.y1; ++py) {
      const glm::vec4* row = &color_[static_cast<size_t>(py - rect_.y0) * ts * count];
      if (count > 1) {
        for (int x = 0; x < width; ++x) {
          glm::vec4 sum = row[static_cast<size_t>(x) * count];
          for (int s = 1; s < count; ++s) sum += row[static_cast<size_t>(x) * count + s];
          resolved_[x] = sum / static_cast<float>(count);
        }
        row = resolved_.data();
      }
      quantize_span(row, &pass_.color->at(rect_.x0, py), static_cast<size_t>(width),
                    pass_.color->format);
    }
    counters.color_store_bytes = pixels * bytes_per_texel(pass_.color->format);
    if (count > 1) counters.resolves = pixels;
  }
  if (pass_.store_depth && pass_.depth) {
    for (int py = rect_.y0; py < rect_.y1; ++py) {
      const float* row = &depth_[static_cast<size_t>(py - rect_.y0) * ts * count];
      for (int px = rect_.x0; px < rect_.x1; ++px) {
        pass_.depth->at(px, py) = quantize(
            glm::vec4(row[static_cast<size_t>(px - rect_.x0) * count]), pass_.depth->format);
      }
    }
    counters.depth_store_bytes = pixels * bytes_per_texel(pass_.depth->format);
  } else if (pass_.store_depth) {
    counters.depth_store_bytes = pixels * config_.depth_stencil_bytes_per_pixel;
  }
}

}  // namespace skinsim::sim
