// List scheduling of tiles over the GPU cores.
#pragma once

#include <vector>

namespace skinsim::gpu_model {

struct TileSchedule {
  std::vector<int> core;          // per job
  std::vector<double> start;      // per job
  std::vector<double> core_busy;  // per core, sum of its jobs
  double makespan = 0.0;
};

// Greedy list schedule: jobs in the given order (row-major tiles), each to the core that frees
// first; ties go to the lowest core index, so the result is deterministic. This is Graham's
// list scheduling (Graham 1969); it models the SGX MP handing the next tile to
// whichever core is idle (dynamic distribution, not a fixed tile-to-core mapping).
TileSchedule list_schedule(const std::vector<double>& durations, int cores);

}  // namespace skinsim::gpu_model
