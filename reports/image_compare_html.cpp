#include "reports/image_compare_html.h"

#include <fmt/format.h>

#include "reports/html_text.h"

namespace skinsim::reports {

const char* const kImageCompareStyle = R"(
.stack { position: relative; max-width: 1024px; } .stack img { width: 100%; display: block; }
.stack img.over { position: absolute; top: 0; left: 0; } .stack { isolation: isolate; }
input.split { width: 100%; max-width: 1024px; }
table.crops th, table.crops td { text-align: center; }
table.crops th { font-size: 0.8em; max-width: 140px; overflow-wrap: anywhere; }
table.crops img { width: 128px; image-rendering: pixelated; } img.bar { vertical-align: middle; }
)";

namespace {

constexpr const char* kCompareScript = R"(
document.querySelectorAll('.compare').forEach(function (c) {
  var over = c.querySelector('img.over'), under = c.querySelector('img.under');
  var split = c.querySelector('input.split');
  function clip() { over.style.clipPath = 'inset(0 ' + (100 - split.value) + '% 0 0)'; }
  split.addEventListener('input', clip);
  c.querySelector('select.left').addEventListener('change', function () { over.src = this.value; });
  c.querySelector('select.right').addEventListener('change', function () { under.src = this.value; });
  c.querySelector('button.flip').addEventListener('click', function () {
    split.value = split.value > 50 ? 0 : 100; clip();
  });
  var diff = c.querySelector('input.diff'), stack = c.querySelector('.stack');
  if (diff) diff.addEventListener('change', function () {
    over.style.mixBlendMode = diff.checked ? 'difference' : '';
    stack.style.filter = diff.checked ? 'brightness(' + diff.value + ')' : '';
    split.disabled = diff.checked;
    if (diff.checked) over.style.clipPath = 'none'; else clip();
  });
  clip();
});
)";

}  // namespace

std::string image_slider_html(const std::vector<std::pair<std::string, std::string>>& frames,
                              std::size_t left, std::size_t right, double difference_gain) {
  const auto options = [&](std::size_t selected) {
    std::string o;
    for (std::size_t i = 0; i < frames.size(); ++i) {
      o += "<option value=\"" + link(frames[i].second) + "\"" + (i == selected ? " selected" : "") +
           ">" + esc(frames[i].first) + "</option>";
    }
    return o;
  };
  std::string h = "<div class=\"compare\">\n<p>Left <select class=\"left\">" + options(left) +
                  "</select> right <select class=\"right\">" + options(right) +
                  "</select> <button type=\"button\" class=\"flip\">flip</button> (drag the "
                  "slider, or flip to alternate the two as FLIP's observer does)";
  if (difference_gain > 0.0) {
    h += fmt::format(
        " <label><input type=\"checkbox\" class=\"diff\" value=\"{0:g}\"> difference</label> "
        "(|left - right| per channel of the display values, x {0:g}: black where they agree)",
        difference_gain);
  }
  h += "</p>\n";
  h += "<div class=\"stack\"><img class=\"under\" src=\"" + link(frames[right].second) +
       "\" alt=\"right image\"><img class=\"over\" src=\"" + link(frames[left].second) +
       "\" alt=\"left image\"></div>\n<input type=\"range\" min=\"0\" max=\"100\" "
       "value=\"50\" class=\"split\">\n</div>\n";
  return h;
}

std::string crop_windows_html(const std::vector<results::CropWindow>& windows) {
  std::string h;
  for (const results::CropWindow& w : windows) {
    if (w.images.empty()) {  // a landmark looked for and not found: only the sentence
      h += "<p><b>" + esc(w.why) + "</b></p>\n";
      continue;
    }
    h += "<p><b>" + esc(w.why) + "</b>: " +
         esc(fmt::format("{}x{} pixels at ({}, {}); below, the {}x{} pixels at ({}, {}) "
                         "magnified {}x",
                         w.size, w.size, w.x, w.y, w.zoom_size, w.zoom_size, w.zoom_x, w.zoom_y,
                         w.zoom)) +
         "</p>\n<table class=\"crops\"><tr>";
    for (const auto& [what, path] : w.images) h += "<th>" + esc(what) + "</th>";
    h += "</tr>\n";
    for (const auto* row : {&w.images, &w.zoomed}) {
      h += "<tr>";
      for (const auto& [what, path] : *row) {
        h += "<td><a href=\"" + link(path) + "\"><img src=\"" + link(path) + "\" alt=\"" +
             esc(what) + "\"></a></td>";
      }
      h += "</tr>\n";
    }
    h += "</table>\n";
  }
  return h;
}

std::string colour_bar_html(const std::string& bar, double gain, const std::string& what) {
  return "<p>Difference colour scale: <img class=\"bar\" src=\"" + link(bar) +
         "\" alt=\"magma colour scale\"> " +
         esc(fmt::format("black = identical, brightest = a difference of 1/{:g} of full scale or "
                         "more (the mean over R, G, B of {} in display values, times {:g})",
                         gain, what, gain)) +
         "</p>\n";
}

std::string image_compare_script() {
  return std::string("<script>") + kCompareScript + "</script>\n";
}

}  // namespace skinsim::reports
