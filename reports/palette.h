// Colours shared by the charts and the SVG timeline, so a pass has one colour everywhere.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "results/sweep_table.h"

namespace skinsim::reports {

using Rgb = std::array<unsigned char, 3>;

// Colour i of a 10-colour qualitative palette (Tableau 10), cycling.
Rgb palette_colour(std::size_t i);

// The pass names of a sweep in first-appearance order (rows, then passes).
std::vector<std::string> pass_order(const results::SweepTable& table);

// A pass's colour, from its index in `order` (the next free index if it is not there) less the
// DRAM wait: palette_colour while `order` has at most 10 passes, else one of 25 colours made
// to be told apart, so every pass of a sweep of up to 25 has its own colour. The frame's DRAM
// wait (results::kDramWaitRow) is always grey.
Rgb pass_colour(const std::string& pass, const std::vector<std::string>& order);

// "#rrggbb".
std::string css_colour(const Rgb& colour);

}  // namespace skinsim::reports
