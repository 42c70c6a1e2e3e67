#include "reports/html_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <future>
#include <optional>
#include <set>

#include "io/atomic_file.h"
#include "reports/csv_writer.h"
#include "reports/error.h"
#include "reports/html_text.h"
#include "reports/image_compare_html.h"
#include "reports/knob_verdicts.h"
#include "reports/palette.h"
#include "reports/pareto.h"
#include "reports/recommendation.h"
#include "reports/report_charts.h"
#include "reports/sequence_sweep.h"
#include "reports/sweep_json.h"
#include "reports/timeline_svg.h"

namespace skinsim::reports {

namespace {

namespace fs = std::filesystem;

constexpr const char* kStyle = R"(
.summary { background: #f4f7fb; border-left: 5px solid #4e79a7; padding: 0.8em 1.2em; }
.recommend { background: #fff5f5; border-left: 5px solid #c80000; padding: 0.8em 1.2em; }
tr.chosen { background: #ffe9e9; font-weight: bold; } tr.over { color: #888; }
figure { margin: 1.5em 0; } figure img { width: 100%; border: 1px solid #ddd; }
.thumbs { display: flex; flex-wrap: wrap; gap: 1em; }
.thumb { font-size: 0.8em; width: 330px; } .thumb img { width: 160px; border: 1px solid #ccc; }
details summary { cursor: pointer; margin: 0.3em 0; } svg.timeline { max-width: 100%; height: auto; }
)";

std::string ms(double v) {
  return fmt::format("{:.2f}", v);
}
std::string mj(double v) {
  return fmt::format("{:.3f}", v);
}
std::string metric_text(double v) {
  return fmt::format("{:.4g}", v);
}
std::string name_of(const results::ConfigResult& r) {
  return r.label.empty() ? r.id : r.label;
}

// Knobs whose value differs between rows (shown per row) and knobs with one value (shown once).
std::pair<std::vector<std::string>, std::map<std::string, std::string>> split_knobs(
    const results::SweepTable& t) {
  std::map<std::string, std::set<std::string>> values;
  for (const results::ConfigResult& r : t.rows) {
    for (const auto& [k, v] : r.knobs) values[k].insert(v);
  }
  std::vector<std::string> varying;
  std::map<std::string, std::string> fixed;
  for (const auto& [k, vs] : values) {
    const bool everywhere =
        std::all_of(t.rows.begin(), t.rows.end(),
                    [&](const results::ConfigResult& r) { return r.knobs.count(k); });
    if (vs.size() == 1 && everywhere)
      fixed[k] = *vs.begin();
    else
      varying.push_back(k);
  }
  return {varying, fixed};
}

std::vector<std::string> metric_names(const results::SweepTable& t) {
  std::set<std::string> names;
  for (const results::ConfigResult& r : t.rows) {
    for (const auto& [k, v] : r.quality) names.insert(k);
  }
  return {names.begin(), names.end()};
}

std::string header_section(const results::SweepTable& t, const ReportOptions& o) {
  std::size_t within = 0;
  for (const results::ConfigResult& r : t.rows) within += r.frame_ms <= t.budget_ms;
  std::string h = "<h1>" + esc(o.title) + "</h1>\n<div class=\"summary\">\n";
  h += "<b>Device:</b> " + esc(t.device) + "<br>\n<b>Scene:</b> " + esc(t.scene) +
       " &nbsp; <b>Resolution:</b> " + esc(t.resolution) + "<br>\n";
  h += "<b>Frame budget:</b> " +
       esc(fmt::format("{:.1f} ms ({:.0f} fps)", t.budget_ms, 1000.0 / t.budget_ms)) + "<br>\n";
  h +=
      fmt::format("<b>Configurations:</b> {} swept, {} within budget<br>\n", t.rows.size(), within);
  h += "<b>Quality metric:</b> " + esc(o.metric_label) + "\n</div>\n";
  return h;
}

// One sentence per knob, per group, from the sweep's own rows (knob_verdicts).
std::string verdicts_section(const results::SweepTable& t, const ReportOptions& o) {
  const std::vector<KnobVerdict> verdicts = knob_verdicts(t, o.quality_metric);
  std::string h = "<h2>What each knob does</h2>\n<div class=\"summary\">\n";
  if (verdicts.empty()) h += "<p>No knob was varied within a group, so none is judged.</p>\n";
  std::optional<std::string> group;
  for (const KnobVerdict& v : verdicts) {
    if (v.group != group) {
      if (group) h += "</ul>\n";
      group = v.group;
      h += "<p><b>" + esc(v.group.empty() ? "All configurations" : v.group) + "</b></p>\n<ul>\n";
    }
    h += "<li>" + esc(v.sentence) + "</li>\n";
  }
  if (group) h += "</ul>\n";
  h += "<p><i>How these are measured:</i> each knob is varied around its technique's finest "
       "configuration (the lowest " +
       esc(o.quality_metric) +
       " against the reference): the configurations that differ from it in that knob alone "
       "give its frame times and, compared with the finest frame, its visible effect (the "
       "visibility rule under Recommendation). " +
       esc(fmt::format("A change under {:g}% of the frame time is reported as no time effect.",
                       kNoTimeEffect * 100.0)) +
       " The technique is judged on each technique's finest configuration against the "
       "group's best.";
  const std::vector<std::string> unswept = unswept_knobs(t);
  if (!unswept.empty()) {
    h +=
        esc(fmt::format(" The other {} knobs had one value wherever they apply, so the sweep "
                        "says nothing about them.",
                        unswept.size()));
  }
  return h + "</p>\n</div>\n";
}

std::string recommendation_section(const results::SweepTable& t, const ReportOptions& o,
                                   const std::vector<Recommendation>& recommendations) {
  std::string h = "<h2>Recommendation</h2>\n<div class=\"recommend\">\n";
  if (std::none_of(t.rows.begin(), t.rows.end(), [&](const results::ConfigResult& r) {
        return r.quality.count(o.quality_metric) > 0;
      })) {
    h += "<p><b>No configuration has the quality metric " + esc(o.quality_metric) +
         ", so none is recommended.</b></p>\n";
  }
  for (const Recommendation& rec : recommendations) {
    h += "<p><b>" + esc(rec.group.empty() ? "All configurations" : rec.group) +
         "</b>: " + esc(rec.verdict) + ".";
    if (rec.chosen) {
      const results::ConfigResult& r = t.rows[*rec.chosen];
      h += " " +
           esc(fmt::format("{:.1f} fps, {} = {:.4g} against the reference, {:.1f} MB DRAM "
                           "per frame.",
                           r.fps, o.quality_metric, r.quality.at(o.quality_metric),
                           r.dram_bytes / 1e6)) +
           "<br>Knobs: ";
      for (const auto& [k, v] : r.knobs) h += "<code>" + esc(k) + "=" + esc(v) + "</code> ";
    }
    h += "</p>\n";
    for (const std::string* note : {&rec.range_note, &rec.runner_up_note}) {
      if (!note->empty()) h += "<p>" + esc(*note) + "</p>\n";
    }
  }
  h += "<p><i>How it is chosen:</i> " + esc(recommendation_rule_text()) + "</p>\n";
  h += "<p><i>Frame-time ranges</i> (low to high) are the cost model re-evaluated with every "
       "uncertain device figure at the end of its plausible range that makes the frame faster, "
       "or slower, all at once; figures that change what the emulator counts (texture cache, "
       "tile size) would need a re-render and are not in the range. <i>Energy</i> is the "
       "dynamic energy of the frame (docs/cost-model.md); its range has every energy figure of "
       "the device profile at its minimum, then at its maximum.</p>\n</div>\n";
  return h + o.after_recommendation;
}

// A slider between any two of the group's full frames (the reference and every configuration,
// the recommended one on the left), with their difference; then per window the crops at 1:1
// and magnified, with the difference's colour scale.
std::string panel_html(const results::SweepTable& t, const results::ComparisonPanel& p,
                       const std::map<std::string, std::string>& truth_images) {
  std::vector<std::pair<std::string, std::string>> frames = {{"reference", p.reference_image}};
  std::size_t left = 0;
  for (const results::ConfigResult& r : t.rows) {
    if (r.group != p.group || r.frame_image.empty()) continue;
    std::string what = r.id == p.chosen ? "recommended: " : r.id == p.best ? "best: " : "";
    if (r.id == p.chosen) left = frames.size();
    frames.emplace_back(what + name_of(r), r.frame_image);
  }
  const auto truth = truth_images.find(p.group);
  if (truth != truth_images.end()) frames.emplace_back("truth (path-traced)", truth->second);
  if (left == 0) {  // a panel from a results.json whose rows lack frames: its own two
    frames.emplace_back("recommended: " + p.chosen, p.chosen_image);
    left = frames.size() - 1;
  }
  return "<h3>" + esc(p.group) + "</h3>\n" + image_slider_html(frames, left, 0, p.difference_gain) +
         crop_windows_html(p.windows) +
         colour_bar_html(p.colour_bar, p.difference_gain,
                         std::string(p.best == p.chosen ? "|recommended - reference|"
                                                        : "|recommended - reference| and "
                                                          "|recommended - best|") +
                             (truth == truth_images.end() ? "" : ", |recommended - truth|"));
}

std::string comparison_section(const results::SweepTable& t, const ReportOptions& o) {
  if (t.panels.empty()) return "";
  std::string h =
      "<h2>What the recommendation looks like</h2>\n<p>Pick any two frames of the group (the "
      "reference or any configuration) for the slider, flip between them, or tick "
      "<i>difference</i> to see where they differ. Below, the windows where the recommended "
      "frame differs most (found in the FLIP error over skin), cut out of the reference, the "
      "best and the recommended frame. Click any image for full size.</p>\n";
  for (const results::ComparisonPanel& p : t.panels) h += panel_html(t, p, o.truth_images);
  return h + image_compare_script();
}

std::string charts_section(const std::vector<ReportFigure>& figures, bool drawn) {
  std::string h = "<h2>Charts</h2>\n";
  if (!drawn) return h + "<p>Charts were not drawn (run without --no-charts to draw them).</p>\n";
  for (const ReportFigure& f : figures) {
    h += "<figure><a href=\"" + link(f.png) + "\"><img src=\"" + link(f.png) + "\" alt=\"" +
         esc(f.caption) + "\"></a>\n<figcaption>" + esc(f.caption);
    if (!f.svg.empty()) h += " (<a href=\"" + link(f.svg) + "\">SVG</a>)";
    h += "</figcaption></figure>\n";
  }
  return h;
}

std::string yes_no(bool v) {
  return v ? "yes" : "no";
}

// Technique error against knob error, per technique and group (technique_errors).
std::string errors_html(const results::SweepTable& t, const ReportOptions& o) {
  const std::vector<TechniqueError> errors = technique_errors(t, o.quality_metric);
  if (errors.empty()) return "";
  std::string h =
      "<p><b>Technique error and knob error.</b> A configuration's " + esc(o.quality_metric) +
      " against the reference mixes two things: what its technique approximates, which even "
      "its best knob values leave (the <i>technique error</i>: the technique's finest "
      "configuration against the reference), and what its own knob values add on top (the "
      "<i>knob error</i>: its frame against that finest frame, the <i>FLIP vs finest</i> "
      "column). A knob error far below the technique error means the knobs are not where the "
      "quality goes.</p>\n<ul>\n";
  for (const TechniqueError& e : errors) {
    h += "<li>" + esc(e.group.empty() ? "" : e.group + ": ") + esc(e.sentence) + "</li>\n";
  }
  h += "</ul>\n";
  std::size_t compared = 0, visible = 0;
  for (const results::ConfigResult& r : t.rows) {
    if (r.reference_image.empty()) continue;
    ++compared;
    visible += r.visible_vs_reference;
  }
  if (compared > 0) {
    h += "<p>" +
         esc(fmt::format(
             "{} of {} configurations differ visibly from the reference (visible vs reference){}",
             visible, compared,
             visible == compared
                 ? ": every technique's best does too, so that column measures the technique "
                   "error, and the knobs are told apart by visible vs finest."
                 : ".")) +
         "</p>\n";
  }
  return h;
}

std::string table_section(const results::SweepTable& t, const ReportOptions& o,
                          const std::set<std::size_t>& chosen) {
  const auto [varying, fixed] = split_knobs(t);
  const std::vector<std::string> metrics = metric_names(t);
  std::set<std::size_t> front;
  for (std::size_t i : pareto_front(t.rows, o.quality_metric, o.higher_is_better)) {
    front.insert(i);
  }
  std::string h = "<h2>Configurations</h2>\n" + errors_html(t, o);
  if (!fixed.empty()) {
    h += "<p>Same for every configuration: ";
    for (const auto& [k, v] : fixed) h += "<code>" + esc(k) + "=" + esc(v) + "</code> ";
    h += "</p>\n";
  }
  h += "<p>Bold: recommended. Grey: over budget. Pareto: on the front of frame time vs " +
       esc(o.quality_metric) +
       ". Visible: whether the frame differs visibly (the rule under Recommendation) from the "
       "reference, and from the best configuration of its own technique in its group "
       "(<i>finest</i>): the knob's cost in quality, apart from what the technique "
       "approximates.</p>\n<div class=\"wide\"><table>\n<tr><th>configuration</th>";
  h += "<th>frame ms</th><th>range ms</th><th>mJ</th><th>range mJ</th><th>" +
       esc(o.quality_metric) +
       "</th><th>visible vs reference</th><th>FLIP vs finest</th><th>visible vs finest</th>";
  for (const std::string& k : varying) h += "<th>" + esc(k) + "</th>";
  h += "<th>fps</th><th>bottleneck</th><th>DRAM MB</th>";
  for (const std::string& m : metrics) {
    if (m != o.quality_metric) h += "<th>" + esc(m) + "</th>";
  }
  h += "<th>Pareto</th></tr>\n";
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const results::ConfigResult& r = t.rows[i];
    const char* cls =
        chosen.count(i) ? " class=\"chosen\"" : (r.frame_ms > t.budget_ms ? " class=\"over\"" : "");
    h += std::string("<tr") + cls + "><td class=\"text\">" + esc(name_of(r)) + "</td>";
    const auto quality = r.quality.find(o.quality_metric);
    h += "<td>" + ms(r.frame_ms) + "</td><td>" + ms(r.frame_ms_low) + "&ndash;" +
         ms(r.frame_ms_high) + "</td><td>" + mj(r.energy_mj) + "</td><td>" + mj(r.energy_mj_low) +
         "&ndash;" + mj(r.energy_mj_high) + "</td><td>" +
         (quality == r.quality.end() ? std::string("-") : metric_text(quality->second)) +
         "</td><td class=\"text\">" +
         (r.reference_image.empty() ? "-" : yes_no(r.visible_vs_reference)) + "</td>";
    if (r.vs_finest && r.vs_finest->against != r.id) {
      h += "<td>" + metric_text(r.vs_finest->flip_mean) + "</td><td class=\"text\">" +
           yes_no(r.vs_finest->visible) + fmt::format(" ({:.0f} px)", r.vs_finest->visible_px) +
           "</td>";
    } else {
      h += std::string("<td>-</td><td class=\"text\">") + (r.vs_finest ? "finest" : "-") + "</td>";
    }
    for (const std::string& k : varying) {
      const std::string v = knob_value(r, k);  // empty: the configuration does not use it
      h += "<td class=\"text\">" + (v.empty() ? std::string("-") : esc(v)) + "</td>";
    }
    h += "<td>" + fmt::format("{:.1f}", r.fps) + "</td><td class=\"text\">" +
         esc(dominant_bottleneck(r)) + "</td><td>" + fmt::format("{:.1f}", r.dram_bytes / 1e6) +
         "</td>";
    for (const std::string& m : metrics) {
      if (m == o.quality_metric) continue;
      auto it = r.quality.find(m);
      h += "<td>" + (it == r.quality.end() ? std::string("-") : metric_text(it->second)) + "</td>";
    }
    h += std::string("<td>") + (front.count(i) ? "yes" : "") + "</td></tr>\n";
  }
  return h + "</table></div>\n";
}

// One row per technique (when the sweep compares several): its best configuration by the
// quality metric, the passes it runs, its DRAM traffic, and the op profile of every skin
// program it runs (eyes and background are the same for all techniques and left out).
std::string techniques_section(const results::SweepTable& t, const ReportOptions& o) {
  std::map<std::string, const results::ConfigResult*> best;
  for (const results::ConfigResult& r : t.rows) {
    const std::string technique = knob_value(r, "technique");
    if (technique.empty()) continue;
    const auto q = r.quality.find(o.quality_metric);
    const results::ConfigResult*& slot = best[technique];
    if (!slot) {
      slot = &r;
      continue;
    }
    const auto q_best = slot->quality.find(o.quality_metric);
    if (q != r.quality.end() &&
        (q_best == slot->quality.end() ||
         (o.higher_is_better ? q->second > q_best->second : q->second < q_best->second))) {
      slot = &r;
    }
  }
  if (best.size() < 2) return "";
  std::string h =
      "<h2>Techniques compared</h2>\n<p>Each technique's best configuration by " +
      esc(o.quality_metric) +
      ". Programs: ALU ops per fragment (vector + scalar + transcendental, from the shader's own "
      "code) and texture reads (independent + dependent), and the fragments each shaded.</p>\n"
      "<table>\n<tr><th>technique</th><th>configuration</th><th>frame ms</th><th>passes (ms)</th>"
      "<th>DRAM MB</th><th>skin programs</th></tr>\n";
  for (const auto& [technique, r] : best) {
    std::string passes, programs;
    for (const results::PassCost& p : merged_passes(*r)) {
      passes += esc(p.name) + " " + ms(p.ms) + "<br>";
    }
    for (const results::ProgramCost& p : r->programs) {
      if (p.program == "background_fs" || p.program == "eye_fs") continue;
      programs +=
          fmt::format("{} ({}): {}+{}+{} ALU, {}+{} tex, {:.2f} M frag<br>", esc(p.program),
                      esc(p.pass), p.vector_ops, p.scalar_ops, p.transcendental_ops,
                      p.texture_reads_independent, p.texture_reads_dependent, p.fragments / 1e6);
    }
    h += "<tr><td class=\"text\">" + esc(technique) + "</td><td class=\"text\">" +
         esc(name_of(*r)) + "</td><td>" + ms(r->frame_ms) + "</td><td class=\"text\">" + passes +
         "</td><td>" + fmt::format("{:.1f}", r->dram_bytes / 1e6) + "</td><td class=\"text\">" +
         programs + "</td></tr>\n";
  }
  return h + "</table>\n";
}

// A thumbnail linking its full-size image; the small copy when the sweep wrote one.
std::string thumbnail(const std::string& dir, const std::string& image, const std::string& alt) {
  const std::string small = thumbnail_path(image);
  const std::string shown = fs::exists(fs::path(dir) / small) ? small : image;
  return "<a href=\"" + link(image) + "\"><img src=\"" + link(shown) + "\" alt=\"" + esc(alt) +
         "\" loading=\"lazy\"></a> ";
}

std::string thumbnails_section(const results::SweepTable& t, const std::string& dir) {
  std::string cells;
  std::set<std::string> references;
  for (const results::ConfigResult& r : t.rows) {
    if (r.reference_image.empty() || !references.insert(r.reference_image).second) continue;
    cells += "<div class=\"thumb\"><div><b>reference</b> (" + esc(r.group) + ")</div>" +
             thumbnail(dir, r.reference_image, "reference") + "</div>\n";
  }
  for (const results::ConfigResult& r : t.rows) {
    if (r.frame_image.empty() && r.error_image.empty()) continue;
    cells += "<div class=\"thumb\"><div>" + esc(name_of(r)) + "</div>";
    for (const std::string* path : {&r.frame_image, &r.error_image}) {
      if (path->empty()) continue;
      const char* what = path == &r.frame_image ? "frame" : "error map";
      cells += thumbnail(dir, *path, std::string(what) + " of " + name_of(r));
    }
    cells += "</div>\n";
  }
  if (cells.empty()) return "";
  return "<h2>Frames and error maps</h2>\n<p>Left: rendered frame; right: error map against the "
         "reference. Click for full size.</p>\n<div class=\"thumbs\">\n" +
         cells + "</div>\n";
}

// Each configuration's frame on the GPU's two stages (PVRTune's view): the recommended ones
// open, the others folded.
std::string timeline_section(const results::SweepTable& t, const std::set<std::size_t>& chosen) {
  const std::vector<std::string> order = pass_order(t);
  std::string h =
      "<h2>Where the frame's time goes: TA and 3D</h2>\n<p>Each pass on the tiler (TA: vertex "
      "shading, binning) and the renderer (3D: hidden-surface removal, shading, resolve) over "
      "the frame, as the cost model schedules them: the TA of a pass runs while the 3D renders "
      "the previous one, so a pass's <i>ms</i> everywhere in this report is its share of the "
      "frame (its render's end minus the previous render's end), and the passes add up to the "
      "frame time. A grey <code>dram_wait</code> at the end is the time the frame's DRAM traffic "
      "outlasts the pipeline. Hover a box for its stage times.</p>\n";
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const results::ConfigResult& r = t.rows[i];
    if (r.passes.empty()) continue;
    h += std::string("<details") + (chosen.count(i) ? " open" : "") + "><summary>" +
         esc(name_of(r)) + (chosen.count(i) ? " (recommended)" : "") + ": " + ms(r.frame_ms) +
         " ms</summary>\n" + timeline_svg(r.passes, order) + "</details>\n";
  }
  return h;
}

std::string assumptions_section(const results::SweepTable& t) {
  std::string h = "<h2>Model assumptions and sensitivity</h2>\n";
  if (t.assumptions.empty()) {
    h += "<p>The sweep recorded no assumptions.</p>\n";
  } else {
    h += "<ul>\n";
    for (const std::string& a : t.assumptions) h += "<li>" + esc(a) + "</li>\n";
    h += "</ul>\n";
  }
  if (t.sensitivity.empty()) return h + "<p>No sensitivity analysis was recorded.</p>\n";
  h += "<p>Frame time of the base configuration when one uncertain figure moves over its "
       "plausible range (others at their base values).</p>\n<table>\n<tr><th>figure</th>"
       "<th>min</th><th>base</th><th>max</th><th>frame ms at min</th><th>at base</th>"
       "<th>at max</th><th>swing ms</th></tr>\n";
  for (const results::SensitivityRow& s : t.sensitivity) {
    const std::string unit = s.unit.empty() ? "" : " " + s.unit;
    const double lo = std::min({s.frame_ms_at_min, s.frame_ms_at_base, s.frame_ms_at_max});
    const double hi = std::max({s.frame_ms_at_min, s.frame_ms_at_base, s.frame_ms_at_max});
    h += "<tr><td class=\"text\">" + esc(s.figure) + "</td>";
    for (double v : {s.min_value, s.base_value, s.max_value}) {
      h += "<td>" + esc(fmt::format("{:g}", v) + unit) + "</td>";
    }
    for (double v : {s.frame_ms_at_min, s.frame_ms_at_base, s.frame_ms_at_max, hi - lo}) {
      h += "<td>" + ms(v) + "</td>";
    }
    h += "</tr>\n";
  }
  return h + "</table>\n";
}

}  // namespace

std::string write_report(const results::SweepTable& table, const std::string& dir,
                         const ReportOptions& options) {
  validate_sweep_table(table);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw ReportError("cannot create report directory " + dir + ": " + ec.message());

  const std::vector<Recommendation> recommendations = recommend(table, options.quality_metric);
  std::set<std::size_t> chosen;
  for (const Recommendation& r : recommendations) {
    if (r.chosen) chosen.insert(*r.chosen);
  }
  const results::ConfigResult* dram_row = !recommendations.empty() && recommendations.front().chosen
                                              ? &table.rows[*recommendations.front().chosen]
                                              : nullptr;
  if (!dram_row && !table.rows.empty()) {
    dram_row =
        &*std::min_element(table.rows.begin(), table.rows.end(),
                           [](const results::ConfigResult& a, const results::ConfigResult& b) {
                             return a.frame_ms < b.frame_ms;
                           });
  }
  std::future<void> alongside;  // its destructor waits, should the charts throw
  if (options.alongside_charts) {
    alongside = std::async(std::launch::async, options.alongside_charts);
  }
  std::vector<ReportFigure> figures;
  if (options.draw_charts && !table.rows.empty()) {
    figures = draw_report_charts(table, dir, options, dram_row);
  }
  if (alongside.valid()) alongside.get();
  if (options.write_data_files) {
    write_sweep_json(table, dir + "/results.json");
    write_sweep_csv(table, dir + "/results.csv");
  }

  std::string page = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  page += "<title>" + esc(options.title) + "</title>\n<style>" + kPageStyle + kStyle +
          kImageCompareStyle + "</style>\n</head>\n";
  const std::string comparison = comparison_section(table, options);
  page += "<body>\n" + header_section(table, options) + verdicts_section(table, options) +
          recommendation_section(table, options, recommendations) + sequence_sweep_section(table) +
          comparison + charts_section(figures, options.draw_charts) +
          timeline_section(table, chosen) + techniques_section(table, options) +
          table_section(table, options, chosen) + thumbnails_section(table, dir) +
          assumptions_section(table);
  if (options.write_data_files) {
    page +=
        "<h2>Data</h2>\n<p><a href=\"results.json\">results.json</a> (everything on this "
        "page; regenerate the report from it) and <a href=\"results.csv\">results.csv</a> (one "
        "row per configuration).</p>\n";
  }
  page += "</body>\n</html>\n";
  const std::string path = (fs::path(dir) / "report.html").string();
  io::write_file_atomically(path, page);
  return path;
}

}  // namespace skinsim::reports
