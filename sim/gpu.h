// The emulated tile-based deferred GPU: executes render passes and counts their work.
#pragma once

#include <tbb/task_arena.h>

#include <functional>
#include <memory>

#include "sim/counters.h"
#include "sim/render_pass.h"

namespace skinsim::sim {

class PassMemo;

class Gpu {
 public:
  explicit Gpu(GpuConfig config);
  ~Gpu();
  Gpu(const Gpu&) = delete;
  Gpu& operator=(const Gpu&) = delete;

  const GpuConfig& config() const { return config_; }

  // Runs one render: vertex stage and binning (TA), then every tile of the render area on
  // the emulated cores (3D), resolving into pass.color. Counters are identical for any
  // host thread count: each emulated core's tiles run in a fixed order on one host task,
  // and per-tile counters are summed in tile order.
  PassCounters execute(const RenderPassDesc& pass);

  // Called with every pass once it has run (its targets hold what it rendered), as a GPU
  // debugger captures a frame: `skinsim export` describes the frame from it.
  void set_pass_capture(std::function<void(const RenderPassDesc&)> capture) {
    capture_ = std::move(capture);
  }
  // Passes identical to one the memo holds are replayed from it, and the others stored in
  // it (sim/pass_memo.h). The memo must outlive the calls to execute.
  void set_pass_memo(PassMemo* memo) { memo_ = memo; }

 private:
  PassCounters execute_impl(const RenderPassDesc& pass);

  GpuConfig config_;
  std::unique_ptr<tbb::task_arena> arena_;
  std::function<void(const RenderPassDesc&)> capture_;
  PassMemo* memo_ = nullptr;
};

// Emulated core a tile is dispatched to: tiles in row-major order, dealt round-robin. The
// real SGX MP dispatch order is unpublished; this is the assumption the texture-cache
// model uses (docs/emulator.md).
int core_of_tile(int tile_index, int cores);

}  // namespace skinsim::sim
