#include "reports/sequence_sweep.h"

#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "reports/csv_writer.h"
#include "reports/error.h"
#include "reports/html_text.h"
#include "results/sweep_table.h"

namespace skinsim::reports {

namespace {

bool any_sequence(const results::SweepTable& table) {
  return std::any_of(table.rows.begin(), table.rows.end(),
                     [](const results::ConfigResult& r) { return r.sequence.has_value(); });
}

std::string csv_number_or_empty(const std::optional<double>& v) {
  return v ? csv_number(*v) : "";
}

// The strips' common axis: 0 to a little past the slowest frame's slow end over the rows, and
// past the budget too when it is within kBudgetReach of that. A budget farther out would
// squeeze every frame into the strip's left end (a 33 ms budget over 2 ms frames), so the axis
// then stops short of it and the budget is drawn off scale: beyond a break at the right end.
struct StripAxis {
  double scale_ms = 0.0;
  double slowest_ms = 0.0;  // the slowest frame's slow end over the rows
  bool budget_on_scale = true;
};
constexpr double kBudgetReach = 2.0;

StripAxis strip_axis(const results::SweepTable& table) {
  double slowest = 0.0;
  for (const results::ConfigResult& r : table.rows) {
    if (r.sequence) slowest = std::max(slowest, r.sequence->max.high);
  }
  if (table.budget_ms <= kBudgetReach * slowest) {
    return {1.05 * std::max(slowest, table.budget_ms), slowest, true};
  }
  return {1.05 * slowest, slowest, false};
}

// Every frame's time as a tick on one horizontal axis shared by the rows (StripAxis), the
// p50, p95 and worst frame marked, and the budget as a dashed red line (past a break when off
// scale).
std::string distribution_svg(const results::SequenceSummary& s, const StripAxis& axis,
                             double budget_ms) {
  constexpr double kWidth = 420.0, kHeight = 26.0;
  // Off scale, the frames' axis leaves room at the right for the break and the budget.
  constexpr double kOffScale = 22.0;
  const double plot = axis.budget_on_scale ? kWidth : kWidth - kOffScale;
  const auto x = [&](double ms) { return fmt::format("{:.1f}", ms / axis.scale_ms * plot); };
  std::string svg =
      fmt::format("<svg width=\"{}\" height=\"{}\" role=\"img\" aria-label=\"frame times of {}\">",
                  kWidth, kHeight, escape_markup(s.name));
  for (double ms : s.frame_ms) {
    svg += fmt::format(
        "<line x1=\"{0}\" x2=\"{0}\" y1=\"6\" y2=\"20\" stroke=\"#888\" stroke-opacity=\"0.5\"/>",
        x(ms));
  }
  const std::pair<const results::SequenceSummary::Stat*, const char*> marks[] = {
      {&s.p50, "#2a7ab0"}, {&s.p95, "#000"}, {&s.max, "#b05a00"}};
  for (const auto& [stat, colour] : marks) {
    svg += fmt::format(
        "<line x1=\"{0}\" x2=\"{1}\" y1=\"23\" y2=\"23\" stroke=\"{2}\" stroke-width=\"2\"/>"
        "<circle cx=\"{3}\" cy=\"13\" r=\"3.5\" fill=\"{2}\"/>",
        x(stat->low), x(stat->high), colour, x(stat->ms));
  }
  const std::string budget_x = axis.budget_on_scale ? x(budget_ms) : fmt::format("{}", kWidth - 4);
  if (!axis.budget_on_scale) {  // an axis break: two slanted strokes between frames and budget
    for (double bx : {plot + 5.0, plot + 9.0}) {
      svg += fmt::format("<line x1=\"{:.1f}\" x2=\"{:.1f}\" y1=\"18\" y2=\"8\" stroke=\"#555\"/>",
                         bx - 2, bx + 2);
    }
  }
  svg += fmt::format(
      "<line x1=\"{0}\" x2=\"{0}\" y1=\"0\" y2=\"{1}\" stroke=\"#d00\" "
      "stroke-dasharray=\"3,2\"><title>budget {2:.1f} ms</title></line>",
      budget_x, kHeight, budget_ms);
  return svg + "</svg>";
}

std::string stat_cell(const results::SequenceSummary::Stat& s) {
  return fmt::format("<td>{:.2f} <small>({:.2f}&ndash;{:.2f})</small></td>", s.ms, s.low, s.high);
}

}  // namespace

std::vector<std::string> sequence_csv_columns(const results::SweepTable& table) {
  if (!any_sequence(table)) return {};
  return {"sequence",
          "frame_ms.p50",
          "frame_ms.p50_low",
          "frame_ms.p50_high",
          "frame_ms.p95",
          "frame_ms.p95_low",
          "frame_ms.p95_high",
          "frame_ms.max",
          "frame_ms.max_low",
          "frame_ms.max_high",
          "temporal_mean_error",
          "temporal_max_error",
          "video"};
}

std::vector<std::string> sequence_csv_cells(const results::SweepTable& table,
                                            const results::ConfigResult& row) {
  if (!any_sequence(table)) return {};
  if (!row.sequence) return std::vector<std::string>(sequence_csv_columns(table).size());
  const results::SequenceSummary& s = *row.sequence;
  return {s.name,
          csv_number(s.p50.ms),
          csv_number(s.p50.low),
          csv_number(s.p50.high),
          csv_number(s.p95.ms),
          csv_number(s.p95.low),
          csv_number(s.p95.high),
          csv_number(s.max.ms),
          csv_number(s.max.low),
          csv_number(s.max.high),
          csv_number_or_empty(s.temporal_mean_error),
          csv_number_or_empty(s.temporal_max_error),
          s.video};
}

std::string sequence_sweep_section(const results::SweepTable& table) {
  if (!any_sequence(table)) return "";
  const StripAxis axis = strip_axis(table);
  const results::SequenceSummary& first =
      *std::find_if(table.rows.begin(), table.rows.end(), [](const results::ConfigResult& r) {
         return r.sequence.has_value();
       })->sequence;
  std::string h = fmt::format(
      "<h2>Frames in motion: {}</h2>\n<p>Every configuration played the sequence <b>{}</b> "
      "({} frames at {:g} fps). <b>The recommendation holds each configuration's p95 frame "
      "time to the {:.1f} ms budget</b>: its frame time in the other sections is the p95 "
      "(nearest rank, with the p95 of its frames' fast and slow ends as the range), while its "
      "frame image, error map and quality are those of frame {}, the same view for every "
      "configuration. Strips: each frame's time as a grey tick on a common axis from 0 to "
      "{:.1f} ms, dots at the p50 (blue), p95 (black) and worst frame (orange) with their "
      "ranges below, the budget dashed red{}. Temporal error: |FLIP(frame t, frame t&minus;1) "
      "&minus; FLIP(reference t, reference t&minus;1)| averaged over the steps "
      "(docs/sequences.md).</p>\n",
      escape_markup(first.name), escape_markup(first.name), first.frames, first.fps,
      table.budget_ms, first.shown_frame, axis.scale_ms,
      axis.budget_on_scale ? ""
                           : fmt::format(" at the right end, off the axis past the break (the "
                                         "slowest frame's slow end is {:.0f}% of it)",
                                         100.0 * axis.slowest_ms / table.budget_ms));
  h += "<table>\n<tr><th class=\"text\">configuration</th><th>frame times</th><th>p50 "
       "ms</th><th>p95 ms</th><th>worst ms</th><th>temporal error mean / worst</th><th "
       "class=\"text\">video</th></tr>\n";
  for (const results::ConfigResult& r : table.rows) {
    if (!r.sequence) continue;
    const results::SequenceSummary& s = *r.sequence;
    h += "<tr><td class=\"text\">" + escape_markup(r.id) + "</td><td>" +
         distribution_svg(s, axis, table.budget_ms) + "</td>" + stat_cell(s.p50) +
         stat_cell(s.p95) + stat_cell(s.max);
    h += s.temporal_mean_error ? fmt::format("<td>{:.4f} / {:.4f}</td>", *s.temporal_mean_error,
                                             *s.temporal_max_error)
                               : "<td></td>";
    if (!s.video.empty()) {
      h += "<td class=\"text\"><video src=\"" + escape_markup(url_encode_path(s.video)) +
           "\" width=\"256\" controls loop muted></video></td>";
    } else if (!s.frames_dir.empty()) {
      h += "<td class=\"text\">no video (ffmpeg absent or failed): <a href=\"" +
           escape_markup(url_encode_path(s.frames_dir)) + "/\">frames</a></td>";
    } else {
      h += "<td></td>";
    }
    h += "</tr>\n";
  }
  return h + "</table>\n";
}

}  // namespace skinsim::reports
