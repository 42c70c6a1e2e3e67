#include "sim/tile_stage.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

#include "sim/texture_cache.h"
#include "sim/texture_line_log.h"
#include "sim/tile_renderer.h"
#include "util/check.h"

namespace skinsim::sim {

namespace {

// A tile's image and counters depend on its inputs alone, so tiles shade on any host thread
// in any order, with one exception: each emulated core's texture cache sees its tiles'
// requests in tile order. So a tile records the cache lines its samples request
// (TextureLineLog), and its core's cache replays the logs in the core's tile order, which
// gives the very hit/miss sequence of shading that core's tiles in order with the cache
// live (the cache only counts; it never changes a texel).
//
// Host threads take tiles in row-major order as they come free. A thread that has shaded a
// tile then replays, through that tile's core, every tile of the core that is shaded and
// next in the core's order, unless another thread is replaying the core already. No
// thread waits for another: a frame uses every host thread, however many cores the device
// has, and only the logs of tiles shaded but not yet replayed are held (a few per thread).
class TileStage {
 public:
  TileStage(const RenderPassDesc& pass, const GpuConfig& config, const SetupTriangles& setup,
            const TileGrid& grid, const TileBins& bins, PassCounters& c)
      : pass_(pass),
        config_(config),
        setup_(setup),
        grid_(grid),
        bins_(bins),
        c_(c),
        tile_count_(static_cast<int>(c.tiles.size())),
        logs_(c.tiles.size()),
        shaded_(c.tiles.size()) {
    for (int core = 0; core < c.cores; ++core) {
      cores_.push_back(std::make_unique<Core>(config.texture_cache));
    }
    // Each core's tiles in tile order, as core_of_tile assigned them (TileCounters::core).
    for (int tile = 0; tile < tile_count_; ++tile)
      cores_[c.tiles[tile].core]->tiles.push_back(tile);
  }

  void run() {
    tbb::parallel_for(0, tbb::this_task_arena::max_concurrency(), [&](int) {
      TileRenderer renderer(pass_, setup_, grid_, config_);  // its tile buffers, reused
      for (int tile = next_tile_++; tile < tile_count_; tile = next_tile_++) {
        shade(renderer, tile);
        replay_ready(c_.tiles[tile].core);
      }
    });
    // A tile marked shaded just as another thread finished replaying its core may be left;
    // every thread is done now, so this replays whatever is.
    for (int core = 0; core < c_.cores; ++core) replay_ready(core);
  }

 private:
  struct Core {
    explicit Core(const TextureCacheConfig& config) : cache(config) {}
    TextureCache cache;      // cold at the start of the render
    std::vector<int> tiles;  // the core's tiles, in the order its cache sees them
    std::mutex replaying;
    std::atomic<std::size_t> next{0};  // index in `tiles` of the next tile to replay
    // The next tile to replay, if it is shaded; -1 otherwise.
    int ready(const std::vector<std::atomic<bool>>& shaded) const {
      const std::size_t i = next.load();
      return i < tiles.size() && shaded[tiles[i]].load() ? tiles[i] : -1;
    }
  };

  void shade(TileRenderer& renderer, int tile) {
    SKINSIM_DCHECK_INDEX(tile, c_.tiles.size());
    TileCounters& tc = c_.tiles[tile];
    if (grid_.in_area(tc.tile_x, tc.tile_y)) {
      logs_[tile] = take_log();
      renderer.render(tc.tile_x, tc.tile_y, bins_.lists[tile], tc, *logs_[tile]);
    }
    shaded_[tile].store(true);
  }

  void replay_ready(int core) {
    Core& k = *cores_[core];
    for (;;) {
      {
        const std::unique_lock lock(k.replaying, std::try_to_lock);
        if (!lock.owns_lock()) return;  // the thread holding it replays what is ready
        for (int tile = k.ready(shaded_); tile >= 0; tile = k.ready(shaded_)) {
          if (logs_[tile]) {  // none outside the render area
            k.cache.replay(*logs_[tile], c_.tiles[tile].texture);
            give_log(std::move(logs_[tile]));
          }
          ++k.next;
        }
      }
      // The next tile may have been marked shaded while this thread held the lock, by a
      // thread that then found the lock taken: replay it here rather than leave it.
      if (k.ready(shaded_) < 0) return;
    }
  }

  // Logs are reused, so a tile's recording rarely allocates.
  std::unique_ptr<TextureLineLog> take_log() {
    {
      const std::lock_guard lock(free_logs_mutex_);
      if (!free_logs_.empty()) {
        std::unique_ptr<TextureLineLog> log = std::move(free_logs_.back());
        free_logs_.pop_back();
        return log;
      }
    }
    return std::make_unique<TextureLineLog>(config_.texture_cache.line_bytes);
  }
  void give_log(std::unique_ptr<TextureLineLog> log) {
    const std::lock_guard lock(free_logs_mutex_);
    free_logs_.push_back(std::move(log));
  }

  const RenderPassDesc& pass_;
  const GpuConfig& config_;
  const SetupTriangles& setup_;
  const TileGrid& grid_;
  const TileBins& bins_;
  PassCounters& c_;
  const int tile_count_;
  std::vector<std::unique_ptr<Core>> cores_;
  std::vector<std::unique_ptr<TextureLineLog>> logs_;  // a tile's, from shading to replay
  std::vector<std::atomic<bool>> shaded_;
  std::atomic<int> next_tile_{0};
  std::mutex free_logs_mutex_;
  std::vector<std::unique_ptr<TextureLineLog>> free_logs_;
};

}  // namespace

void render_tiles(const RenderPassDesc& pass, const GpuConfig& config, const SetupTriangles& setup,
                  const TileGrid& grid, const TileBins& bins, PassCounters& c) {
  TileStage(pass, config, setup, grid, bins, c).run();
}

}  // namespace skinsim::sim
