// The HTML pieces that show two frames against each other, shared by report.html's comparison
// panels and compare.html: a slider between two of several full frames (with a flip button
// that alternates them, as FLIP's observer does), the crop tables of CropWindows at 1:1 and
// magnified, and the difference images' colour bar. Self-contained: no network fetches.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "results/sweep_table.h"

namespace skinsim::reports {

// CSS rules the pieces below need (append to the page's style).
extern const char* const kImageCompareStyle;

// A slider between frames[left] (shown left of the split) and frames[right]; the selects offer
// every frame. Frames are (label, relative path). With `difference_gain` > 0 a checkbox shows
// |left - right| instead, x difference_gain, for whichever two frames are selected: the
// browser blends them (CSS mix-blend-mode: difference, then brightness), so any pair works
// without a difference image per pair and without reading pixels in script (which a page
// opened from file:// may not do). Needs image_compare_script() on the page.
std::string image_slider_html(const std::vector<std::pair<std::string, std::string>>& frames,
                              std::size_t left, std::size_t right, double difference_gain = 0.0);

// Per window: what it shows and where, and its crops at 1:1 above the magnified ones.
std::string crop_windows_html(const std::vector<results::CropWindow>& windows);

// "Difference colour scale: [bar] black = identical, ...": `what` names the difference shown,
// e.g. "|recommended - reference|".
std::string colour_bar_html(const std::string& bar, double gain, const std::string& what);

// The <script> that drives every slider on the page; once, after the last slider.
std::string image_compare_script();

}  // namespace skinsim::reports
