// Exec4: the Exec language over four fragments at once (values: shader_lanes.h), what the
// tile renderer shades a tile's visible fragments in, four consecutive ones of a draw at a
// time. Per lane it computes what Exec computes for that fragment alone, bit for bit:
//   - inputs are ExecFragIn's interpolation, done in lanes with the same operations;
//   - texture reads are the Exec texture unit's for each fragment: 2D reads and shadow-map
//     comparisons have their footprints addressed four fragments at a time
//     (ExecTexUnit::sample_lanes), cube reads go one by one; each fragment's cache-line
//     requests are kept apart and appended to the tile's log lane 0 first (end()): the order of
//     shading the four one after the other, which the texture cache replays
//     (texture_line_log.h);
//   - lanes past the batch's last fragment are padding: they repeat an input and read nothing.
#pragma once

#include <array>

#include "shading/shader_lanes.h"
#include "sim/shader_io.h"
#include "util/check.h"

namespace skinsim::sim {

template <int N>
struct Varying4 {
  sl::Lanes<N> value;
  sl::Lanes<N> ddx;
  sl::Lanes<N> ddy;
  Varying<N> lane(int l) const { return {value.lane(l), ddx.lane(l), ddy.lane(l)}; }
};

template <int N>
Varying4<N> scaled(const Varying4<N>& v, float s) {
  return {v.value * s, v.ddx * s, v.ddy * s};
}

// The interpolated inputs of four fragments, evaluated in lanes with ExecFragIn's operations.
class Exec4FragIn {
 public:
  // One fragment: its triangle's varying planes and 1/w plane, the pixel centre relative to
  // the triangle's origin, and the pixel centre itself.
  struct Fragment {
    const Plane* planes;
    const Plane* inv_w;
    float rel_x, rel_y;
    glm::vec2 frag_coord;
  };
  Exec4FragIn(const std::array<Fragment, sl::kLanes>& fragments, glm::vec2 inv_target_size)
      : fragments_(fragments), inv_size_(inv_target_size) {
    for (int l = 0; l < sl::kLanes; ++l) {
      rx_[l] = fragments[l].rel_x;
      ry_[l] = fragments[l].rel_y;
    }
    const Plane* const inv_w[] = {fragments[0].inv_w, fragments[1].inv_w, fragments[2].inv_w,
                                  fragments[3].inv_w};
    inv_w_dx_ = gather(inv_w, &Plane::dx);
    inv_w_dy_ = gather(inv_w, &Plane::dy);
    w_ = 1.0f / at(inv_w);
  }

  sl::LFloat f(int slot) const {
    sl::LFloat r;
    r.c[0] = value(slot);
    return r;
  }
  sl::Lanes<2> v2(int slot) const { return values<2>(slot); }
  sl::Lanes<3> v3(int slot) const { return values<3>(slot); }
  sl::Lanes<4> v4(int slot) const { return values<4>(slot); }
  Varying4<2> texcoord(int slot) const { return grad<2>(slot); }
  Varying4<3> direction(int slot) const { return grad<3>(slot); }
  sl::Lanes<2> frag_coord() const {
    sl::Lanes<2> r;
    for (int l = 0; l < sl::kLanes; ++l) r.set_lane(l, fragments_[l].frag_coord);
    return r;
  }
  Varying4<2> screen_texcoord() const {
    Varying4<2> r;
    r.value = frag_coord() * inv_size_;
    r.ddx = sl::Lanes<2>(glm::vec2(inv_size_.x, 0.0f));
    r.ddy = sl::Lanes<2>(glm::vec2(0.0f, inv_size_.y));
    return r;
  }
  // Fragment l's inputs as the Exec language reads them.
  ExecFragIn lane(int l) const {
    const Fragment& f = fragments_[l];
    return ExecFragIn(f.planes, *f.inv_w, f.rel_x, f.rel_y, f.frag_coord, inv_size_);
  }

 private:
  template <class Planes>
  static Float4 gather(const Planes& planes, float Plane::*part) {
    return Float4{planes[0]->*part, planes[1]->*part, planes[2]->*part, planes[3]->*part};
  }
  // Plane::at in each lane.
  template <class Planes>
  Float4 at(const Planes& planes) const {
    return gather(planes, &Plane::c) + gather(planes, &Plane::dx) * rx_ +
           gather(planes, &Plane::dy) * ry_;
  }
  std::array<const Plane*, sl::kLanes> slot_planes(int slot) const {
    SKINSIM_DCHECK_INDEX(slot, kMaxVaryings);
    return {fragments_[0].planes + slot, fragments_[1].planes + slot, fragments_[2].planes + slot,
            fragments_[3].planes + slot};
  }
  Float4 value(int slot) const { return at(slot_planes(slot)) * w_; }
  template <int N>
  sl::Lanes<N> values(int slot) const {
    sl::Lanes<N> r;
    for (int i = 0; i < N; ++i) r.c[i] = value(slot + i);
    return r;
  }
  // ExecFragIn::grad in each lane.
  template <int N>
  Varying4<N> grad(int slot) const {
    Varying4<N> r;
    for (int i = 0; i < N; ++i) {
      const std::array<const Plane*, sl::kLanes> p = slot_planes(slot + i);
      const Float4 u = at(p) * w_;
      r.value.c[i] = u;
      r.ddx.c[i] = (gather(p, &Plane::dx) - u * inv_w_dx_) * w_;
      r.ddy.c[i] = (gather(p, &Plane::dy) - u * inv_w_dy_) * w_;
    }
    return r;
  }

  std::array<Fragment, sl::kLanes> fragments_;
  glm::vec2 inv_size_;
  Float4 rx_, ry_, w_, inv_w_dx_, inv_w_dy_;
};

class Exec4TexUnit {
 public:
  // `line_bytes`: the texture cache's line, as in the tile logs `tex` records into.
  Exec4TexUnit(ExecTexUnit& tex, std::uint32_t line_bytes) : tex_(tex) {
    lines_.fill(TextureLineLog(line_bytes));
  }

  // A batch of `fragments` (1 to 4) whose requests go, at end(), to the log `tex` records
  // into now (the tile's).
  void begin(int fragments) {
    active_ = fragments;
    tile_lines_ = tex_.lines();
    for (TextureLineLog& l : lines_) l.clear();  // keeps its capacity for the next batch
  }
  void end() {
    for (int l = 0; l < active_; ++l) tile_lines_->append(lines_[l]);
    tex_.set_lines(tile_lines_);
  }
  // The Exec texture unit, recording for lane `l` (a program that runs lane by lane).
  ExecTexUnit& lane(int l) {
    tex_.set_lines(&lines_[l]);
    return tex_;
  }
  int fragments() const { return active_; }

  sl::Lanes<4> sample(int b, const Varying4<2>& uv) {
    std::array<Varying<2>, sl::kLanes> at;
    for (int l = 0; l < sl::kLanes; ++l) at[l] = uv.lane(l);
    return packed([&](glm::vec4* out) { tex_.sample_lanes(b, at, active_, lines_.data(), out); });
  }
  sl::Lanes<4> sample(int b, const sl::Lanes<2>& uv) { return sample_lod(b, uv, 0.0f); }
  sl::Lanes<4> sample_lod(int b, const sl::Lanes<2>& uv, const sl::LFloat& lod) {
    std::array<glm::vec2, sl::kLanes> at;
    std::array<float, sl::kLanes> lods;
    for (int l = 0; l < sl::kLanes; ++l) {
      at[l] = uv.lane(l);
      lods[l] = lod.lane(l);
    }
    return packed(
        [&](glm::vec4* out) { tex_.sample_lod_lanes(b, at, lods, active_, lines_.data(), out); });
  }
  sl::Lanes<4> sample_cube(int b, const Varying4<3>& d) {
    return each<4>([&](int l) { return lane(l).sample_cube(b, d.lane(l)); });
  }
  sl::Lanes<4> sample_cube_lod(int b, const sl::Lanes<3>& d, const sl::LFloat& lod) {
    return each<4>([&](int l) { return lane(l).sample_cube_lod(b, d.lane(l), lod.lane(l)); });
  }
  sl::LFloat sample_shadow(int b, const Varying4<3>& coord) {
    return shadow(b, coord.value, false);
  }
  sl::LFloat sample_shadow(int b, const sl::Lanes<3>& coord) { return shadow(b, coord, true); }
  // N reads per fragment (ExecTexUnit::sample_each), the coordinates computed once for all
  // four lanes.
  template <int N, class Coord>
  std::array<sl::Lanes<4>, N> sample_each(int b, const Coord& coord) {
    using Coords = decltype(coord(0));
    std::array<Coords, N> coords;
    for (int i = 0; i < N; ++i) coords[i] = coord(i);
    std::array<sl::Lanes<4>, N> out;
    for (int l = 0; l < active_; ++l) {
      const std::array<glm::vec4, N> v =
          lane(l).template sample_each<N>(b, [&](int i) { return coords[i].lane(l); });
      for (int i = 0; i < N; ++i) out[i].set_lane(l, v[i]);
    }
    return out;
  }

 private:
  sl::LFloat shadow(int b, const sl::Lanes<3>& coord, bool dependent) {
    std::array<glm::vec3, sl::kLanes> at;
    for (int l = 0; l < sl::kLanes; ++l) at[l] = coord.lane(l);
    std::array<float, sl::kLanes> v{};
    tex_.sample_shadow_lanes(b, at, dependent, active_, lines_.data(), v.data());
    sl::LFloat r;
    r.c[0] = Float4{v[0], v[1], v[2], v[3]};
    return r;
  }
  // The values `read` writes for the batch's fragments, in lanes.
  template <class Read>
  sl::Lanes<4> packed(Read read) {
    std::array<glm::vec4, sl::kLanes> v{};
    read(v.data());
    sl::Lanes<4> r;
    for (int l = 0; l < sl::kLanes; ++l) r.set_lane(l, v[l]);
    return r;
  }
  // fn(l) of each of the batch's fragments l, read one by one.
  template <int N, class Fn>
  sl::Lanes<N> each(Fn fn) {
    sl::Lanes<N> r;
    for (int l = 0; l < active_; ++l) r.set_lane(l, fn(l));
    return r;
  }

  ExecTexUnit& tex_;
  int active_ = 0;
  TextureLineLog* tile_lines_ = nullptr;
  std::array<TextureLineLog, sl::kLanes> lines_;  // each fragment's requests
};

// Fragment programs only; a mediump program runs lane by lane in ExecMediump.
struct Exec4 {
  static constexpr bool kExecutes = true;
  using f32 = sl::LFloat;
  using vec2 = sl::Lanes<2>;
  using vec3 = sl::Lanes<3>;
  using vec4 = sl::Lanes<4>;
  using FragIn = Exec4FragIn;
  using TexUnit = Exec4TexUnit;
};

}  // namespace skinsim::sim
