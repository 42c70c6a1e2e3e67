// How far a replayed render target is from the emulator's: the figures the llvmpipe
// cross-check reports and its test holds to stated tolerances.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace skinsim::crosscheck {

// Both images are float RGBA, row-major, the same size. For a depth target only the first
// channel is compared. Gives psnr_db (peak 1, or the emulator's largest value when above),
// max_abs, and differing_fraction: the share of pixels whose largest channel difference
// exceeds `differing_above` (1.5/255 of the peak for colour, 1e-4 for depth).
nlohmann::json compare_targets(const std::vector<float>& emulated,
                               const std::vector<float>& replayed, int width, int height,
                               bool depth);

// One line of the report: pass, PSNR, max difference, differing pixels.
std::string format_row(const nlohmann::json& result);

}  // namespace skinsim::crosscheck
