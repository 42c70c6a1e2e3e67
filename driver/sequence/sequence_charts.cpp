#include "driver/sequence/sequence_charts.h"

#include <algorithm>

#include "gpu_model/timing.h"
#include "reports/display_check.h"
#include "reports/sequence_charts.h"
#include "results/pass_rows.h"

namespace skinsim::driver {

SequenceChartsOutcome write_sequence_charts(const Sequence& sequence, const SequenceResult& result,
                                            const std::string& title,
                                            const std::filesystem::path& dir) {
  SequenceChartsOutcome outcome;
  if (!reports::charts_available(&outcome.note)) {
    outcome.display_attempt_pending = reports::abandoned_display_attempts() > 0;
    return outcome;
  }
  reports::SequenceSeries s;
  s.title = title;
  s.budget_ms = 1000.0 / sequence.fps;
  // Stacked in the order of the frame with the most passes (the full pipeline, not a LOD
  // frame's single pass), others after them, and the DRAM wait on top as in the frame table.
  std::vector<const SequenceFrame*> by_passes;
  for (const SequenceFrame& f : result.frames) by_passes.push_back(&f);
  std::stable_sort(by_passes.begin(), by_passes.end(), [](const auto* a, const auto* b) {
    return a->passes.size() > b->passes.size();
  });
  for (const SequenceFrame* f : by_passes) {
    for (const SequencePass& p : f->passes) {
      if (std::find(s.pass_names.begin(), s.pass_names.end(), p.name) == s.pass_names.end()) {
        s.pass_names.push_back(p.name);
      }
    }
  }
  std::stable_partition(s.pass_names.begin(), s.pass_names.end(),
                        [](const std::string& name) { return name != results::kDramWaitRow; });
  s.pass_ms.assign(s.pass_names.size(), std::vector<double>(result.frames.size(), 0.0));
  for (std::size_t i = 0; i < result.frames.size(); ++i) {
    const SequenceFrame& f = result.frames[i];
    s.time_s.push_back(f.time_s);
    s.frame_ms.push_back(f.range.base);
    s.low_ms.push_back(f.range.low);
    s.high_ms.push_back(f.range.high);
    for (const SequencePass& p : f.passes) {
      const auto k = std::find(s.pass_names.begin(), s.pass_names.end(), p.name);
      s.pass_ms[static_cast<std::size_t>(k - s.pass_names.begin())][i] = p.ms;
    }
  }
  // Quality only when every frame has it (a run with the reference).
  s.quality_label = "flip_skin";
  for (const SequenceFrame& f : result.frames) {
    if (!f.quality.count("flip_skin")) s.quality_label = "flip_frame";
  }
  for (const SequenceFrame& f : result.frames) {
    if (f.quality.count(s.quality_label)) s.quality.push_back(f.quality.at(s.quality_label));
    if (f.temporal) s.temporal_error.push_back(f.temporal->error());
  }
  std::vector<std::pair<const char*, decltype(&reports::write_sequence_frame_chart)>> charts = {
      {"sequence_frame_ms", &reports::write_sequence_frame_chart},
      {"sequence_passes", &reports::write_sequence_pass_chart}};
  if (s.quality.size() == result.frames.size() && result.frames.size() > 1) {
    charts.emplace_back("sequence_quality", &reports::write_sequence_quality_chart);
  }
  for (const auto& [stem, draw] : charts) {
    const reports::ChartFiles files = draw(s, (dir / stem).string(), {});
    for (const std::string& path : {files.png, files.svg}) {
      if (!path.empty()) outcome.written.push_back(std::filesystem::path(path).filename());
    }
  }
  outcome.display_attempt_pending = reports::abandoned_display_attempts() > 0;
  return outcome;
}

}  // namespace skinsim::driver
