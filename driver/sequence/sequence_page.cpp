#include "driver/sequence/sequence_page.h"

#include <fmt/format.h>

#include "driver/sequence/sequence_video.h"
#include "io/atomic_file.h"
#include "reports/html_text.h"

namespace skinsim::driver {

SequencePage write_sequence_page(const std::filesystem::path& dir, const std::string& frames_dir,
                                 const Sequence& sequence, const SequenceResult& result,
                                 const std::string& title, const std::vector<std::string>& charts) {
  SequencePage page;
  const std::string video = "sequence.webm";
  const VideoOutcome encoded = encode_sequence_video(dir / frames_dir, sequence.fps, dir / video);
  const nlohmann::json summary = sequence_json(sequence, result);
  const FrameMsStats& s = result.stats;
  std::string h = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>{0}</title>"
      "\n<style>{1}</style>\n</head>\n<body>\n<h1>{0}</h1>\n<p>{2} frames at {3:g} fps "
      "({4:.2f} s); frame budget {5:.1f} ms.</p>\n",
      escape_markup(fmt::format("skinsim: sequence {}, {}", sequence.name, title)),
      reports::kPageStyle, sequence.frames, sequence.fps, sequence.frames / sequence.fps,
      1000.0 / sequence.fps);
  if (encoded.encoded) {
    page.written.push_back(video);
    h += "<video src=\"" + video + "\" controls loop muted autoplay></video>\n";
  } else {
    page.note = encoded.note;
    h += "<p>No video: " + escape_markup(encoded.note) + ". The frames: <a href=\"" +
         escape_markup(reports::url_encode_path(frames_dir)) + "/\">" + escape_markup(frames_dir) +
         "/</a>.</p>\n";
  }
  h += fmt::format(
      "<h2>Frame time</h2>\n<table>\n<tr><th>p50</th><th>p95</th><th>p99</th><th>worst</th>"
      "<th>mean</th><th class=\"text\">worst frame</th></tr>\n<tr><td>{:.3f}</td><td>{:.3f}</td>"
      "<td>{:.3f}</td><td>{:.3f}</td><td>{:.3f}</td><td class=\"text\">{} ({:.3f} s)</td></tr>"
      "\n</table>\n<p>Milliseconds, nearest-rank percentiles over the frames.</p>\n",
      s.p50, s.p95, s.p99, s.max, s.mean, s.worst_frame, sequence.time_s(s.worst_frame));
  if (summary.contains("temporal")) {
    const nlohmann::json& t = summary["temporal"];
    h += fmt::format(
        "<h2>Temporal stability</h2>\n<p>|FLIP(frame t, frame t&minus;1) &minus; FLIP(reference "
        "t, reference t&minus;1)|: mean {:.4f}, worst {:.4f} into frame {} "
        "(docs/sequences.md).</p>\n",
        t["mean_error"].get<double>(), t["max_error"].get<double>(),
        t["worst_step"]["index"].get<int>());
  }
  for (const std::string& chart : charts) {
    if (chart.ends_with(".png"))
      h += "<p><img src=\"" + escape_markup(chart) + "\" alt=\"\" style=\"max-width:100%\"></p>\n";
  }
  io::write_file_atomically((dir / "sequence.html").string(), h + "</body>\n</html>\n");
  page.written.push_back("sequence.html");
  return page;
}

}  // namespace skinsim::driver
