#include "reports/timeline_svg.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "reports/html_text.h"
#include "reports/palette.h"

namespace skinsim::reports {

namespace {

constexpr double kWidth = 960.0;
constexpr double kLeft = 44.0;  // lane titles
constexpr double kRight = 16.0;
constexpr double kLaneHeight = 30.0;
constexpr double kTaTop = 8.0;
constexpr double kRenderTop = kTaTop + kLaneHeight + 8.0;
constexpr double kAxisY = kRenderTop + kLaneHeight + 6.0;
constexpr double kLegendTop = kAxisY + 50.0;
constexpr double kLegendItemWidth = 180.0;
constexpr double kLegendRowHeight = 20.0;
constexpr double kCharWidth = 7.0;  // of the 12 px sans-serif labels, to decide what fits

// Tick spacing of 1, 2 or 5 x 10^k giving at most ~10 ticks over `span`.
double tick_step(double span) {
  const double raw = span / 10.0;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (double f : {1.0, 2.0, 5.0}) {
    if (f * magnitude >= raw) return f * magnitude;
  }
  return 10.0 * magnitude;
}

// Dark text on light colours, white on dark (ITU-R BT.601 luma).
const char* text_colour(const Rgb& c) {
  return 0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2] > 150.0 ? "#1a1a1a" : "#ffffff";
}

std::string box(double x0, double x1, double top, const results::PassCost& p, const Rgb& colour,
                const std::string& tooltip) {
  const double w = std::max(1.0, x1 - x0);
  std::string s = fmt::format(
      "<g><title>{}</title><rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.0f}\" "
      "fill=\"{}\" stroke=\"#ffffff\"/>",
      escape_markup(tooltip), x0, top, w, kLaneHeight, css_colour(colour));
  if (w > kCharWidth * static_cast<double>(p.name.size()) + 6.0) {
    s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\" fill=\"{}\">{}</text>",
                     x0 + w / 2.0, top + kLaneHeight / 2.0 + 4.0, text_colour(colour),
                     escape_markup(p.name));
  }
  return s + "</g>\n";
}

}  // namespace

std::string timeline_svg(const std::vector<results::PassCost>& passes,
                         const std::vector<std::string>& colour_order) {
  double end_ms = 0.0;
  for (const results::PassCost& p : passes)
    end_ms = std::max({end_ms, p.render_end_ms, p.ta_end_ms});
  const double span = end_ms > 0.0 ? end_ms : 1.0;
  const double scale = (kWidth - kLeft - kRight) / span;
  const auto x_at = [&](double ms) { return kLeft + ms * scale; };

  const std::size_t legend_per_row = static_cast<std::size_t>((kWidth - kLeft) / kLegendItemWidth);
  const std::size_t legend_rows = (passes.size() + legend_per_row - 1) / legend_per_row;
  const double height = kLegendTop + static_cast<double>(legend_rows) * kLegendRowHeight + 4.0;

  std::string s = fmt::format(
      "<svg class=\"timeline\" xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" "
      "height=\"{:.0f}\" viewBox=\"0 0 {:.0f} {:.0f}\" font-family=\"sans-serif\" "
      "font-size=\"12\" role=\"img\">\n",
      kWidth, height, kWidth, height);
  s += fmt::format("<text x=\"4\" y=\"{:.1f}\">TA</text><text x=\"4\" y=\"{:.1f}\">3D</text>\n",
                   kTaTop + kLaneHeight / 2.0 + 4.0, kRenderTop + kLaneHeight / 2.0 + 4.0);
  for (double top : {kTaTop, kRenderTop}) {
    s += fmt::format(
        "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.0f}\" fill=\"#f2f2f2\"/>\n",
        kLeft, top, kWidth - kLeft - kRight, kLaneHeight);
  }
  for (const results::PassCost& p : passes) {
    const Rgb colour = pass_colour(p.name, colour_order);
    const std::string times = fmt::format(
        "{}: TA {:.3f}-{:.3f} ms, 3D {:.3f}-{:.3f} ms; its share of the frame {:.3f} ms", p.name,
        p.ta_start_ms, p.ta_end_ms, p.render_start_ms, p.render_end_ms, p.ms);
    if (p.ta_end_ms > p.ta_start_ms) {
      s += box(x_at(p.ta_start_ms), x_at(p.ta_end_ms), kTaTop, p, colour, times);
    }
    if (p.render_end_ms > p.render_start_ms) {
      s += box(x_at(p.render_start_ms), x_at(p.render_end_ms), kRenderTop, p, colour, times);
    }
  }
  const double step = tick_step(span);
  for (double t = 0.0; t <= span * (1.0 + 1e-9); t += step) {
    s += fmt::format(
        "<line x1=\"{0:.1f}\" x2=\"{0:.1f}\" y1=\"{1:.1f}\" y2=\"{2:.1f}\" stroke=\"#999\"/>"
        "<text x=\"{0:.1f}\" y=\"{3:.1f}\" text-anchor=\"middle\">{4:g}</text>\n",
        x_at(t), kAxisY, kAxisY + 5.0, kAxisY + 18.0, t);
  }
  s += fmt::format(
      "<line x1=\"{0:.1f}\" x2=\"{0:.1f}\" y1=\"{1:.1f}\" y2=\"{2:.1f}\" stroke=\"#c00000\" "
      "stroke-dasharray=\"5,3\" stroke-width=\"2\"/>\n",
      x_at(end_ms), kTaTop - 4.0, kAxisY);
  s += fmt::format(
      "<text x=\"{:.1f}\" y=\"{:.1f}\">time from the start of the frame (ms); the frame ends at "
      "{:.2f} ms (dashed red line)</text>\n",
      kLeft, kAxisY + 36.0, end_ms);
  for (std::size_t i = 0; i < passes.size(); ++i) {
    const double x = kLeft + static_cast<double>(i % legend_per_row) * kLegendItemWidth;
    const double y = kLegendTop + static_cast<double>(i / legend_per_row) * kLegendRowHeight;
    s += fmt::format(
        "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"12\" height=\"12\" fill=\"{}\"/>"
        "<text x=\"{:.1f}\" y=\"{:.1f}\">{} {:.2f} ms</text>\n",
        x, y, css_colour(pass_colour(passes[i].name, colour_order)), x + 16.0, y + 10.5,
        escape_markup(passes[i].name), passes[i].ms);
  }
  return s + "</svg>\n";
}

}  // namespace skinsim::reports
