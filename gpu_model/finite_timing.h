// The model's guarantee that no NaN or infinity leaves it: every modelled time, byte count
// and ratio is finite. The loader bounds every profile figure (FigureSpec) so that this holds
// for any emulator counters; a failure here is a bug in skinsim (SKINSIM_CHECK), not bad input.
#pragma once

#include "gpu_model/timing.h"

namespace skinsim::gpu_model {

void check_finite(const PassTiming& pass);
void check_finite(const FrameTiming& frame);

}  // namespace skinsim::gpu_model
