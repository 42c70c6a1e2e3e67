#include "reports/sequence_sweep.h"

#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "reports/error.h"
#include "reports/html_text.h"
#include "results/sweep_table.h"

namespace skinsim::reports {

namespace {

bool any_sequence(const results::SweepTable& table) {
  return std::any_of(table.rows.begin(), table.rows.end(),
                     [](const results::ConfigResult& r) { return r.sequence.has_value(); });
}

std::string number(double v) {
  return fmt::format("{}", v);
}

std::string optional_number(const std::optional<double>& v) {
  return v ? number(*v) : "";
}

// Every frame's time as a tick on one horizontal axis shared by the rows (0 to `scale_ms`),
// the p50, p95 and worst frame marked, and the budget as a dashed red line.
std::string distribution_svg(const results::SequenceSummary& s, double scale_ms, double budget_ms) {
  constexpr double kWidth = 420.0, kHeight = 26.0;
  const auto x = [&](double ms) { return fmt::format("{:.1f}", ms / scale_ms * kWidth); };
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
  svg += fmt::format(
      "<line x1=\"{0}\" x2=\"{0}\" y1=\"0\" y2=\"{1}\" stroke=\"#d00\" stroke-dasharray=\"3,2\"/>",
      x(budget_ms), kHeight);
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
          number(s.p50.ms),
          number(s.p50.low),
          number(s.p50.high),
          number(s.p95.ms),
          number(s.p95.low),
          number(s.p95.high),
          number(s.max.ms),
          number(s.max.low),
          number(s.max.high),
          optional_number(s.temporal_mean_error),
          optional_number(s.temporal_max_error),
          s.video};
}

std::string sequence_sweep_section(const results::SweepTable& table) {
  if (!any_sequence(table)) return "";
  double scale_ms = table.budget_ms;
  for (const results::ConfigResult& r : table.rows) {
    if (r.sequence) scale_ms = std::max(scale_ms, r.sequence->max.high);
  }
  scale_ms *= 1.05;
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
      "ranges below, the budget dashed red. Temporal error: |FLIP(frame t, frame t&minus;1) "
      "&minus; FLIP(reference t, reference t&minus;1)| averaged over the steps "
      "(docs/sequences.md).</p>\n",
      escape_markup(first.name), escape_markup(first.name), first.frames, first.fps,
      table.budget_ms, first.shown_frame, scale_ms);
  h += "<table>\n<tr><th class=\"text\">configuration</th><th>frame times</th><th>p50 "
       "ms</th><th>p95 ms</th><th>worst ms</th><th>temporal error mean / worst</th><th "
       "class=\"text\">video</th></tr>\n";
  for (const results::ConfigResult& r : table.rows) {
    if (!r.sequence) continue;
    const results::SequenceSummary& s = *r.sequence;
    h += "<tr><td class=\"text\">" + escape_markup(r.id) + "</td><td>" +
         distribution_svg(s, scale_ms, table.budget_ms) + "</td>" + stat_cell(s.p50) +
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
