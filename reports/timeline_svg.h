// A frame's passes on the GPU's two stages over time, as PVRTune shows them: one lane for the
// tiler (TA: vertex shading, binning) and one for the renderer (3D: per-tile HSR, shading,
// resolve). It makes the cost model's overlap visible: the TA of a pass runs while the 3D
// renders the previous one (docs/cost-model.md, "Frame").
#pragma once

#include <string>
#include <vector>

#include "results/sweep_table.h"

namespace skinsim::reports {

// Inline SVG (no external references) of `passes` (one frame, in submission order, with their
// schedules), coloured by reports::pass_colour(name, colour_order). Each box has a tooltip
// with its stage times; a legend lists each pass's share of the frame.
std::string timeline_svg(const std::vector<results::PassCost>& passes,
                         const std::vector<std::string>& colour_order);

}  // namespace skinsim::reports
