// Rows of a frame's pass list that are not render passes, by name: the cost model's tables,
// the sweep's results and the reports' colours all name them so.
#pragma once

namespace skinsim::results {

// The frame's exposed DRAM wait: the time its memory traffic outlasts the pipeline
// (gpu_model::FrameTiming::dram_wait_ms), shown as a row after the passes.
inline constexpr const char* kDramWaitRow = "dram_wait";

}  // namespace skinsim::results
