#include "results/sequence_summary.h"

#include <nlohmann/json.hpp>

#include "results/error.h"
#include "results/sweep_table.h"

namespace skinsim::results {
namespace {

nlohmann::json stat_json(const SequenceSummary::Stat& s) {
  return {{"ms", s.ms}, {"low", s.low}, {"high", s.high}};
}

SequenceSummary::Stat parse_stat(const nlohmann::json& j) {
  return {j.at("ms").get<double>(), j.at("low").get<double>(), j.at("high").get<double>()};
}

}  // namespace

void to_json(nlohmann::json& j, const SequenceSummary& v) {
  j = {{"name", v.name},
       {"frames", v.frames},
       {"fps", v.fps},
       {"shown_frame", v.shown_frame},
       {"frame_ms_p50", stat_json(v.p50)},
       {"frame_ms_p95", stat_json(v.p95)},
       {"frame_ms_max", stat_json(v.max)},
       {"percentiles", "nearest rank"},
       {"frame_ms", v.frame_ms},
       {"video", v.video},
       {"frames_dir", v.frames_dir}};
  if (v.temporal_mean_error) j["temporal_mean_error"] = *v.temporal_mean_error;
  if (v.temporal_max_error) j["temporal_max_error"] = *v.temporal_max_error;
}

SequenceSummary parse_sequence_summary(const nlohmann::json& j, const std::string& where) {
  try {
    SequenceSummary s;
    s.name = j.at("name").get<std::string>();
    s.frames = j.at("frames").get<int>();
    s.fps = j.at("fps").get<double>();
    s.shown_frame = j.at("shown_frame").get<int>();
    s.p50 = parse_stat(j.at("frame_ms_p50"));
    s.p95 = parse_stat(j.at("frame_ms_p95"));
    s.max = parse_stat(j.at("frame_ms_max"));
    s.frame_ms = j.at("frame_ms").get<std::vector<double>>();
    s.video = j.at("video").get<std::string>();
    s.frames_dir = j.at("frames_dir").get<std::string>();
    if (j.contains("temporal_mean_error")) {
      s.temporal_mean_error = j["temporal_mean_error"].get<double>();
      s.temporal_max_error = j.at("temporal_max_error").get<double>();
    }
    return s;
  } catch (const nlohmann::json::exception& e) {
    throw ResultsError(where + ": " + e.what());
  }
}

void apply_sequence_summary(ConfigResult& row, const SequenceSummary& summary) {
  row.frame_ms = summary.p95.ms;
  row.frame_ms_low = summary.p95.low;
  row.frame_ms_high = summary.p95.high;
  row.fps = 1000.0 / summary.p95.ms;
  row.sequence = summary;
}

}  // namespace skinsim::results
