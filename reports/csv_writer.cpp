#include "reports/csv_writer.h"

#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "io/atomic_file.h"
#include "reports/error.h"
#include "reports/sequence_sweep.h"

namespace skinsim::reports {

namespace {

struct Columns {
  std::vector<std::string> knobs;
  std::vector<std::string> passes;
  std::vector<std::string> metrics;
};

Columns collect_columns(const results::SweepTable& table) {
  std::set<std::string> knobs;
  std::set<std::string> metrics;
  Columns c;
  for (const results::ConfigResult& r : table.rows) {
    for (const auto& [k, v] : r.knobs) knobs.insert(k);
    for (const auto& [k, v] : r.quality) metrics.insert(k);
    for (const results::PassCost& p : r.passes) {
      if (std::find(c.passes.begin(), c.passes.end(), p.name) == c.passes.end()) {
        c.passes.push_back(p.name);
      }
    }
  }
  c.knobs.assign(knobs.begin(), knobs.end());
  c.metrics.assign(metrics.begin(), metrics.end());
  return c;
}

void append_record(std::string& out, const std::vector<std::string>& fields) {
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) out += ',';
    out += csv_field(fields[i]);
  }
  out += '\n';
}

std::string yes_no(bool value) {
  return value ? "yes" : "no";
}

}  // namespace

std::string csv_number(double v) {
  return fmt::format("{}", v);
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char ch : text) {
    if (ch == '"') out += '"';
    out += ch;
  }
  return out + "\"";
}

std::vector<std::string> sweep_csv_columns(const results::SweepTable& table) {
  const Columns c = collect_columns(table);
  std::vector<std::string> cols = {"id", "label"};
  cols.insert(cols.end(), c.knobs.begin(), c.knobs.end());
  cols.insert(cols.end(), {"frame_ms", "frame_ms_low", "frame_ms_high", "fps", "dram_bytes",
                           "energy_mj", "energy_mj_low", "energy_mj_high"});
  for (const std::string& p : c.passes) {
    cols.push_back(p + ".ms");
    cols.push_back(p + ".bottleneck");
  }
  cols.insert(cols.end(), c.metrics.begin(), c.metrics.end());
  cols.insert(cols.end(),
              {"visible_vs_reference", "group", "finest", "knob_flip", "knob_visible_px",
               "knob_visible", "best", "vs_best_flip", "vs_best_visible_px", "vs_best_visible"});
  const std::vector<std::string> sequence = sequence_csv_columns(table);
  cols.insert(cols.end(), sequence.begin(), sequence.end());
  std::set<std::string> seen;
  for (const std::string& col : cols) {
    if (!seen.insert(col).second) {
      throw ReportError("sweep CSV: column '" + col +
                        "' would appear twice (a knob, pass or quality metric reuses the name)");
    }
  }
  return cols;
}

std::string sweep_csv(const results::SweepTable& table) {
  const std::vector<std::string> cols = sweep_csv_columns(table);
  const Columns c = collect_columns(table);
  std::string out;
  append_record(out, cols);
  for (const results::ConfigResult& r : table.rows) {
    const std::vector<results::PassCost> passes = merged_passes(r);
    std::vector<std::string> cells = {r.id, r.label};
    for (const std::string& k : c.knobs) cells.push_back(knob_value(r, k));
    cells.insert(cells.end(),
                 {csv_number(r.frame_ms), csv_number(r.frame_ms_low), csv_number(r.frame_ms_high),
                  csv_number(r.fps), csv_number(r.dram_bytes), csv_number(r.energy_mj),
                  csv_number(r.energy_mj_low), csv_number(r.energy_mj_high)});
    for (const std::string& name : c.passes) {
      auto it = std::find_if(passes.begin(), passes.end(),
                             [&](const results::PassCost& p) { return p.name == name; });
      cells.push_back(it == passes.end() ? "" : csv_number(it->ms));
      cells.push_back(it == passes.end() ? "" : it->bottleneck);
    }
    for (const std::string& m : c.metrics) {
      auto it = r.quality.find(m);
      cells.push_back(it == r.quality.end() ? "" : csv_number(it->second));
    }
    cells.push_back(r.reference_image.empty() ? "" : yes_no(r.visible_vs_reference));
    cells.push_back(r.group);
    for (const std::optional<results::FrameComparison>& against : {r.vs_finest, r.vs_best}) {
      if (!against) {
        cells.insert(cells.end(), {"", "", "", ""});
        continue;
      }
      cells.insert(cells.end(), {against->against, csv_number(against->flip_mean),
                                 csv_number(against->visible_px), yes_no(against->visible)});
    }
    const std::vector<std::string> sequence = sequence_csv_cells(table, r);
    cells.insert(cells.end(), sequence.begin(), sequence.end());
    append_record(out, cells);
  }
  return out;
}

void write_sweep_csv(const results::SweepTable& table, const std::string& path) {
  io::write_file_atomically(path, sweep_csv(table));
}

}  // namespace skinsim::reports
