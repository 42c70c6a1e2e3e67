// Crops of fixed landmarks (an eye, the lips, ...) and of the windows where two frames differ
// most: found in a FLIP error map (the window of the largest error sum, then the next one not
// overlapping it), cut out of several images at 1:1 and magnified 4x around the landmark or
// the window's largest error, plus the amplified difference image and its colour scale. Used by the
// sweep's comparison panels and by `skinsim compare`.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "driver/sweep/crop_landmarks.h"
#include "image/image.h"
#include "results/sweep_table.h"

namespace skinsim::driver {

// Difference images show |a - b| per pixel (the mean over R, G and B of the display-encoded
// values) times this gain, on the magma scale: a difference of 1/8 of full scale or more is
// the brightest colour.
inline constexpr double kDifferenceGain = 8.0;

// FLIP error of `test` against `against`, zero outside `mask` (if any): where to look.
image::ScalarMap flip_error_map(const image::Image& test, const image::Image& against,
                                const image::Mask* mask);

// |a - b| x kDifferenceGain on the magma scale.
image::Image amplified_difference(const image::Image& a, const image::Image& b);

// Writes the difference images' colour scale (256x16, black to brightest) to `path`.
void write_colour_bar(const std::filesystem::path& path);

// A named error map to search for a window, and a named image to cut out of it.
using NamedMap = std::pair<std::string, image::ScalarMap>;
using NamedImage = std::pair<std::string, const image::Image*>;

// One window centred on each landmark (crop_landmarks.h), then one per search (each avoiding
// the previous search's; none where the error is zero); every image cut out of each at 1:1
// and magnified, written to dir/<stem>_w<window>_<image>.png and _x4.png. The windows' paths
// are relative to `dir`. After the landmarks' windows, one without images for each sentence of
// `not_found` (landmarks looked for and not found), so the report says so where they would be.
std::vector<results::CropWindow> write_crop_windows(const std::vector<Landmark>& landmarks,
                                                    const std::vector<NamedMap>& searches,
                                                    const std::vector<NamedImage>& images,
                                                    const std::filesystem::path& dir,
                                                    const std::string& stem,
                                                    const std::vector<std::string>& not_found = {});

}  // namespace skinsim::driver
