#include "gpu_model/tile_schedule.h"

#include <algorithm>

namespace skinsim::gpu_model {

TileSchedule list_schedule(const std::vector<double>& durations, int cores) {
  TileSchedule s;
  s.core.resize(durations.size());
  s.start.resize(durations.size());
  s.core_busy.assign(static_cast<std::size_t>(std::max(cores, 1)), 0.0);
  std::vector<double> free_at(s.core_busy.size(), 0.0);
  for (std::size_t job = 0; job < durations.size(); ++job) {
    // min_element returns the first minimum: lowest index wins ties.
    const auto it = std::min_element(free_at.begin(), free_at.end());
    const auto c = static_cast<std::size_t>(it - free_at.begin());
    s.core[job] = static_cast<int>(c);
    s.start[job] = free_at[c];
    free_at[c] += durations[job];
    s.core_busy[c] += durations[job];
  }
  s.makespan = *std::max_element(free_at.begin(), free_at.end());
  return s;
}

}  // namespace skinsim::gpu_model
