// A frame's modelled passes in the form the reports draw them (results::PassCost): each
// pass's share of the frame, its bottleneck, DRAM bytes by cause and its TA/3D schedule, plus
// the frame's DRAM wait when it is bandwidth-bound, so the entries add up to frame_ms.
#pragma once

#include <vector>

#include "gpu_model/timing.h"
#include "results/sweep_table.h"

namespace skinsim::driver {

std::vector<results::PassCost> pass_costs(const gpu_model::FrameTiming& timing);

}  // namespace skinsim::driver
