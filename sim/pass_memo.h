// Replays render passes that were already rendered with exactly the same inputs. A sweep's
// configurations share most of their passes: the shadow map is the same in all of them, and
// the irradiance and its blurs are the same for every LUT size at one buffer scale. An
// emulated pass is a pure function of what it reads (every core's texture cache starts cold
// at each render, Gpu::execute_impl), so the targets it wrote and the counters it made can
// be replayed bit for bit instead of emulated again.
//
// A pass is identified by a 128-bit XXH3 hash of everything the render reads (pass_key): the
// GPU configuration, the pass's targets and load/store actions, and per draw the geometry's
// bytes, the programs (their C++ type and their GLSL source, which has the uniforms inlined
// as constants), the bound textures' texels and samplers and the fixed-function state.
// Nothing is trusted to a knob table, so a technique or knob added later cannot be replayed
// wrongly; a change to any input is a miss.
//
// Not thread-safe: one memo per frame in flight.
#pragma once

#include <cstddef>
#include <cstdint>
#include <list>
#include <optional>
#include <unordered_map>
#include <vector>

#include "sim/counters.h"
#include "sim/render_pass.h"

namespace skinsim::sim {

struct PassKey {
  std::uint64_t low = 0;
  std::uint64_t high = 0;
  bool operator==(const PassKey&) const = default;
};

// The hash of everything `pass` reads on a GPU configured as `config` (threads aside: the
// results do not depend on them). Nullopt when a program cannot describe itself as GLSL, so
// the pass is not memoized.
std::optional<PassKey> pass_key(const RenderPassDesc& pass, const GpuConfig& config);

class PassMemo {
 public:
  // Entries beyond `capacity_bytes` of stored pixels are evicted, least recently used first.
  explicit PassMemo(std::size_t capacity_bytes);

  // Before a pass runs: the passes of this frame whose targets it samples are worth keeping
  // (end_frame).
  void note_sampled(const RenderPassDesc& pass);
  // The counters of an identical pass rendered earlier, with its stored targets written into
  // `pass`'s; nullopt when there is none.
  std::optional<PassCounters> replay(const PassKey& key, const RenderPassDesc& pass);
  // Keeps what `pass` just rendered, under `key`, until the frame ends.
  void store(const PassKey& key, const RenderPassDesc& pass, const PassCounters& counters);
  // Ends a frame. What it stored and a later pass of it sampled is kept for later frames; the
  // rest is dropped: such a pass drew the frame's image, which depends on the very knobs a
  // sweep varies, so keeping it would hold memory for no replay.
  void end_frame();

  struct Stats {
    int replayed = 0;  // passes replayed
    int rendered = 0;  // passes looked up and not found
    std::size_t bytes = 0;
  };
  const Stats& stats() const { return stats_; }

 private:
  struct KeyHash {
    std::size_t operator()(const PassKey& k) const { return static_cast<std::size_t>(k.low); }
  };
  // A target's pixels as stored, in a quarter of the floats the emulator holds them in where
  // that is exact: RGBA8 ones as their bytes, depth ones as their red channel (the others
  // are 0); anything else as floats.
  struct StoredPixels {
    std::vector<std::uint8_t> unorm8;
    std::vector<float> depth;
    std::vector<glm::vec4> floats;
    std::size_t bytes() const {
      return unorm8.size() + depth.size() * sizeof(float) + floats.size() * sizeof(glm::vec4);
    }
  };
  struct Entry {
    PassKey key;
    PassCounters counters;
    std::optional<StoredPixels> color;  // when the pass stores its colour
    std::optional<StoredPixels> depth;  // when the pass keeps a depth target
    std::size_t bytes() const {
      return (color ? color->bytes() : 0) + (depth ? depth->bytes() : 0);
    }
  };
  // A pass this frame stored, and where its targets' pixels are while the frame runs.
  struct Stored {
    Entry entry;
    const glm::vec4* color = nullptr;
    const glm::vec4* depth = nullptr;
    bool sampled = false;
  };

  static StoredPixels pack(const RenderTarget& target);
  static void unpack(const StoredPixels& stored, RenderTarget& target);
  void erase(const PassKey& key);

  std::size_t capacity_bytes_;
  std::list<Entry> entries_;  // most recently used first
  std::unordered_map<PassKey, std::list<Entry>::iterator, KeyHash> index_;
  std::vector<Stored> this_frame_;
  Stats stats_;
};

}  // namespace skinsim::sim
