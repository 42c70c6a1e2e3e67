#include "sim/pass_memo.h"

#include <xxhash.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <typeinfo>

#include "util/parallel_pixels.h"
#include "util/unorm8.h"

namespace skinsim::sim {

namespace {

// Bumped when the key's layout changes, so no two layouts can collide.
constexpr std::uint32_t kKeyVersion = 2;

struct StateDeleter {
  void operator()(XXH3_state_t* s) const { XXH3_freeState(s); }
};

// Feeds values to the hash, each with its size so that adjacent fields cannot run together.
class KeyWriter {
 public:
  KeyWriter() : state_(XXH3_createState()) {
    if (!state_ || XXH3_128bits_reset(state_.get()) == XXH_ERROR) throw std::bad_alloc();
  }
  void bytes(const void* data, std::size_t size) {
    value(static_cast<std::uint64_t>(size));
    if (size) XXH3_128bits_update(state_.get(), data, size);
  }
  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T> && std::has_unique_object_representations_v<T>);
    XXH3_128bits_update(state_.get(), &v, sizeof v);
  }
  void number(float v) { value(std::bit_cast<std::uint32_t>(v)); }
  void text(const std::string& s) { bytes(s.data(), s.size()); }
  template <class T>
  void array(const T* data, std::size_t count) {
    value(data != nullptr);
    if (data) bytes(data, count * sizeof(T));
  }
  PassKey finish() const {
    const XXH128_hash_t h = XXH3_128bits_digest(state_.get());
    return {h.low64, h.high64};
  }

 private:
  std::unique_ptr<XXH3_state_t, StateDeleter> state_;
};

void write_pixels(KeyWriter& w, const std::vector<glm::vec4>& pixels) {
  w.bytes(pixels.data(), pixels.size() * sizeof(glm::vec4));
}

void write_texture(KeyWriter& w, const Texture2D* t) {
  w.value(t != nullptr);
  if (!t) return;
  w.value(static_cast<std::uint8_t>(t->format()));
  w.value(static_cast<std::uint8_t>(t->sampler().filter));
  w.value(static_cast<std::uint8_t>(t->sampler().wrap));
  w.value(t->level_count());
  for (int i = 0; i < t->level_count(); ++i) {
    const LevelView& l = t->level(i);
    w.value(l.width);
    w.value(l.height);
    w.bytes(l.texels, static_cast<std::size_t>(l.width) * l.height * sizeof(glm::vec4));
  }
}

void write_target(KeyWriter& w, const RenderTarget* t, bool with_pixels) {
  w.value(t != nullptr);
  if (!t) return;
  w.value(t->width);
  w.value(t->height);
  w.value(static_cast<std::uint8_t>(t->format));
  if (with_pixels) write_pixels(w, t->pixels);
}

// A program as the key sees it: its C++ type (the code Exec runs) and its GLSL source (the
// same code with the uniforms as constants, floats printed so that they read back exactly).
template <class Program>
void write_program(KeyWriter& w, const Program* p) {
  w.value(p != nullptr);
  if (!p) return;
  w.text(typeid(*p).name());
  w.text(p->name());
  w.text(p->glsl(sl::GlslDialect::kEs300).source);
}

bool binds_textures(const RenderPassDesc& pass) {
  return std::any_of(pass.draws.begin(), pass.draws.end(), [](const DrawCall& d) {
    return std::any_of(d.textures.textures.begin(), d.textures.textures.end(),
                       [](const Texture2D* t) { return t != nullptr; }) ||
           std::any_of(d.textures.cubes.begin(), d.textures.cubes.end(),
                       [](const TextureCube* c) { return c != nullptr; });
  });
}

}  // namespace

std::optional<PassKey> pass_key(const RenderPassDesc& pass, const GpuConfig& config) {
  KeyWriter w;
  w.value(kKeyVersion);
  w.value(config.tile_size);
  w.value(config.cores);
  w.value(config.depth_stencil_bytes_per_pixel);
  // A pass that samples nothing does not meet the texture cache (a shadow map, say), so it
  // is the same under any cache geometry (`run --sensitivity` varies it).
  if (binds_textures(pass)) {
    w.value(config.texture_cache.size_bytes);
    w.value(config.texture_cache.line_bytes);
    w.value(config.texture_cache.associativity);
    w.value(static_cast<std::uint8_t>(config.texture_cache.set_index));
  }

  w.text(pass.name);
  // What a render does not overwrite stays as it was, so it is part of the input: the whole
  // target when it is loaded or only an area is rendered.
  const bool partial = pass.render_area.has_value();
  write_target(w, pass.color, pass.color_load == LoadOp::kLoad || partial);
  w.value(static_cast<std::uint8_t>(pass.color_load));
  for (int i = 0; i < 4; ++i) w.number(pass.clear_color[i]);
  w.value(pass.store_color);
  w.value(pass.samples);
  w.value(static_cast<std::uint8_t>(pass.depth_load));
  w.value(pass.store_depth);
  write_target(w, pass.depth, partial);
  w.value(partial);
  if (partial) {
    w.value(pass.render_area->x0);
    w.value(pass.render_area->y0);
    w.value(pass.render_area->x1);
    w.value(pass.render_area->y1);
  }

  w.value(pass.draws.size());
  for (const DrawCall& d : pass.draws) {
    const Geometry& g = d.geometry;
    w.value(g.vertex_count);
    w.array(g.attributes.positions, g.vertex_count);
    w.array(g.attributes.normals, g.vertex_count);
    w.array(g.attributes.uvs, g.vertex_count);
    w.array(g.attributes.tangents, g.vertex_count);
    w.array(g.attributes.thickness, g.vertex_count);
    w.array(g.indices, g.index_count);
    try {
      write_program(w, d.vertex_program.get());
      write_program(w, d.fragment_program.get());
    } catch (const std::exception&) {
      return std::nullopt;  // a program without GLSL: rendered every time
    }
    for (const Texture2D* t : d.textures.textures) write_texture(w, t);
    for (const TextureCube* c : d.textures.cubes) {
      w.value(c != nullptr);
      if (c) {
        for (int face = 0; face < 6; ++face) write_texture(w, &c->face(face));
      }
    }
    w.value(static_cast<std::uint8_t>(d.cull));
    w.value(static_cast<std::uint8_t>(d.blend));
    w.value(d.depth_test);
    w.value(d.depth_write);
  }
  return w.finish();
}

PassMemo::PassMemo(std::size_t capacity_bytes) : capacity_bytes_(capacity_bytes) {}

PassMemo::StoredPixels PassMemo::pack(const RenderTarget& target) {
  StoredPixels s;
  if (target.format == TexelFormat::kRGBA8) {
    // A stored RGBA8 value is one of the 256 (quantize); a value that is not (one the host
    // wrote) keeps the target in floats. On every thread: the final pass's target is packed in
    // every frame.
    s.unorm8.resize(target.pixels.size() * 4);
    std::atomic<bool> exact = true;
    for_each_pixel(target.pixels.size(), [&](std::size_t i) {
      for (int c = 0; c < 4; ++c) {
        const std::optional<std::uint8_t> k = unorm8_code(target.pixels[i][c]);
        if (!k) exact.store(false, std::memory_order_relaxed);
        s.unorm8[i * 4 + c] = k.value_or(0);
      }
    });
    if (exact) return s;
    s.unorm8 = {};
  }
  if (is_depth_format(target.format)) {
    // quantize() stores depth in red and 0 in the rest; a bit pattern other than +0 (one the
    // host wrote) keeps the target in floats.
    s.depth.resize(target.pixels.size());
    std::atomic<bool> exact = true;
    for_each_pixel(target.pixels.size(), [&](std::size_t i) {
      const glm::vec4& p = target.pixels[i];
      if (std::bit_cast<std::uint32_t>(p.y) != 0 || std::bit_cast<std::uint32_t>(p.z) != 0 ||
          std::bit_cast<std::uint32_t>(p.w) != 0) {
        exact.store(false, std::memory_order_relaxed);
      }
      s.depth[i] = p.x;
    });
    if (exact) return s;
    s.depth = {};
  }
  s.floats = target.pixels;
  return s;
}

void PassMemo::unpack(const StoredPixels& stored, RenderTarget& target) {
  if (!stored.unorm8.empty()) {
    for_each_pixel(target.pixels.size(), [&](std::size_t i) {
      for (int c = 0; c < 4; ++c) target.pixels[i][c] = kUnorm8Value[stored.unorm8[i * 4 + c]];
    });
  } else if (!stored.depth.empty()) {
    for_each_pixel(target.pixels.size(), [&](std::size_t i) {
      target.pixels[i] = glm::vec4(stored.depth[i], 0.0f, 0.0f, 0.0f);
    });
  } else {
    std::copy(stored.floats.begin(), stored.floats.end(), target.pixels.begin());
  }
}

void PassMemo::note_sampled(const RenderPassDesc& pass) {
  const auto sampled = [&pass](const glm::vec4* pixels) {
    if (!pixels) return false;
    for (const DrawCall& d : pass.draws) {
      for (const Texture2D* t : d.textures.textures) {
        if (t && t->level(0).texels == pixels) return true;
      }
      for (const TextureCube* c : d.textures.cubes) {
        for (int face = 0; c && face < 6; ++face) {
          if (c->face(face).level(0).texels == pixels) return true;
        }
      }
    }
    return false;
  };
  for (Stored& s : this_frame_) s.sampled = s.sampled || sampled(s.color) || sampled(s.depth);
}

std::optional<PassCounters> PassMemo::replay(const PassKey& key, const RenderPassDesc& pass) {
  const auto it = index_.find(key);
  if (it == index_.end()) {
    ++stats_.rendered;
    return std::nullopt;
  }
  entries_.splice(entries_.begin(), entries_, it->second);
  const Entry& e = *it->second;
  if (e.color) unpack(*e.color, *pass.color);
  if (e.depth) unpack(*e.depth, *pass.depth);
  ++stats_.replayed;
  return e.counters;
}

void PassMemo::store(const PassKey& key, const RenderPassDesc& pass, const PassCounters& counters) {
  Stored s;
  s.entry.key = key;
  s.entry.counters = counters;
  if (pass.color && pass.store_color) {
    s.entry.color = pack(*pass.color);
    s.color = pass.color->pixels.data();
  }
  if (pass.depth) {
    s.entry.depth = pack(*pass.depth);
    s.depth = pass.depth->pixels.data();
  }
  this_frame_.push_back(std::move(s));
}

void PassMemo::end_frame() {
  for (Stored& s : this_frame_) {
    if (!s.sampled || s.entry.bytes() > capacity_bytes_) continue;
    erase(s.entry.key);
    stats_.bytes += s.entry.bytes();
    entries_.push_front(std::move(s.entry));
    index_[entries_.front().key] = entries_.begin();
  }
  this_frame_.clear();
  while (stats_.bytes > capacity_bytes_) erase(entries_.back().key);
}

void PassMemo::erase(const PassKey& key) {
  const auto it = index_.find(key);
  if (it == index_.end()) return;
  stats_.bytes -= it->second->bytes();
  entries_.erase(it->second);
  index_.erase(it);
}

}  // namespace skinsim::sim
