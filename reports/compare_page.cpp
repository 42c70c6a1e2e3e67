#include "reports/compare_page.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "io/atomic_file.h"
#include "reports/compare_table.h"
#include "reports/html_text.h"
#include "reports/image_compare_html.h"

namespace skinsim::reports {

namespace {

constexpr const char* kStyle = R"(
.same { background: #f2f9f2; border-left: 5px solid #2e7d32; padding: 0.8em 1.2em; }
.different { background: #fff5f5; border-left: 5px solid #c80000; padding: 0.8em 1.2em; }
tr.moved { background: #fff0f0; }
)";

std::string number(const std::optional<double>& v) {
  return v ? fmt::format("{:.6g}", *v) : "-";
}

std::string summary(const Comparison& c) {
  const bool different = c.different();
  std::string h = std::string("<div class=\"") + (different ? "different" : "same") + "\">\n";
  h += "<b>A:</b> <code>" + esc(c.a) + "</code><br>\n<b>B:</b> <code>" + esc(c.b) + "</code><br>\n";
  h += "<b>Result:</b> " +
       std::string(different ? "different beyond tolerances (exit status 1)"
                             : "the same within tolerances (exit status 0)") +
       "<br>\n" +
       (c.kind == "run" ? "<b>Frame time:</b> " + esc(frame_time_text(c.configs.front())) + "<br>\n"
                        : "") +
       "<b>Tolerances:</b> " + esc(tolerances_text(c.tolerances)) +
       ", relative to A's value.\n</div>\n";
  return h;
}

std::string changes_section(const Comparison& c) {
  std::string h = "<h2>What changed</h2>\n";
  if (c.changes.empty()) return h + "<p>Nothing: " + esc(kNoChangeText) + ".</p>\n";
  h += "<table>\n<tr><th class=\"text\">setting</th><th class=\"text\">A</th><th "
       "class=\"text\">B</th></tr>\n";
  for (const SettingChange& s : c.changes) {
    h += "<tr><td class=\"text\"><b>" + esc(s.name) + "</b></td><td class=\"text\">" + esc(s.a) +
         "</td><td class=\"text\">" + esc(s.b) + "</td></tr>\n";
  }
  return h + "</table>\n";
}

std::string moved_table(const ConfigDiff& d) {
  if (d.moved.empty()) {
    return fmt::format("<p>None of the {} values moved beyond its tolerance.</p>\n",
                       d.values_compared);
  }
  std::string h = fmt::format(
      "<p>{} of {} values moved beyond their tolerance, largest relative change first.</p>\n"
      "<div class=\"wide\"><table>\n<tr><th class=\"text\">value</th><th "
      "class=\"text\">kind</th><th>A</th><th>B</th>"
      "<th>change</th></tr>\n",
      d.moved.size(), d.values_compared);
  for (const ValueDelta& v : d.moved) {
    h += "<tr><td class=\"text\">" + esc(v.name) + "</td><td class=\"text\">" + esc(v.kind) +
         "</td><td>" + number(v.a) + "</td><td>" + number(v.b) + "</td><td>" + esc(change_text(v)) +
         "</td></tr>\n";
  }
  return h + "</table></div>\n";
}

std::string image_section(const Comparison& c, const ImageDiff& d) {
  std::string h = "<p><b>Frames:</b> " + esc(image_verdict_text(d)) + ".</p>\n";
  std::vector<std::pair<std::string, std::string>> frames = {{"A", d.a_image}, {"B", d.b_image}};
  if (!d.difference_image.empty()) {
    frames.emplace_back(fmt::format("|B - A| x {:g}", c.difference_gain), d.difference_image);
  }
  h += image_slider_html(frames, 1, 0) + crop_windows_html(d.windows);
  if (!d.difference_image.empty()) h += colour_bar_html(c.colour_bar, c.difference_gain, "|B - A|");
  return h;
}

// The runs' other images with links to both, for which pass changed; no verdict.
std::string other_images_section(const std::vector<ImageChange>& images) {
  if (images.empty()) return "";
  std::string h =
      "<h2>Other images</h2>\n<p>Which pixels moved in the runs' other images (largest change "
      "of a channel in display values); shown to tell which pass changed, not judged.</p>\n"
      "<table>\n<tr><th class=\"text\">image</th><th class=\"text\">pixels</th>"
      "<th class=\"text\">A</th><th class=\"text\">B</th></tr>\n";
  const auto link = [](const std::string& path, const char* side) {
    if (path.empty()) return std::string("-");
    return "<a href=\"" + esc(url_encode_path(path)) + "\">" + side + "</a>";
  };
  for (const ImageChange& i : images) {
    h += "<tr><td class=\"text\">" + esc(i.name) + "</td><td class=\"text\">" +
         esc(image_change_text(i)) + "</td><td class=\"text\">" + link(i.a_image, "A") +
         "</td><td class=\"text\">" + link(i.b_image, "B") + "</td></tr>\n";
  }
  return h + "</table>\n";
}

std::string run_sections(const Comparison& c) {
  const ConfigDiff& run = c.configs.front();
  return "<h2>What moved</h2>\n" + moved_table(run) + "<h2>Frames</h2>\n" +
         (run.image ? image_section(c, *run.image) : "<p>No frames to compare.</p>\n") +
         other_images_section(run.other_images);
}

std::string anchor(const std::string& id) {
  return esc(url_encode_path("config-" + id));
}

std::string sweep_sections(const Comparison& c) {
  std::string h = "<h2>Configurations</h2>\n";
  h += fmt::format("<p>{} in both sweeps, {} only in B, {} only in A.</p>\n", c.configs.size(),
                   c.added.size(), c.removed.size());
  for (const auto& [what, ids] :
       {std::pair{"Only in B (added)", &c.added}, std::pair{"Only in A (removed)", &c.removed}}) {
    if (ids->empty()) continue;
    h += std::string("<p><b>") + what + ":</b> ";
    for (const std::string& id : *ids) h += "<code>" + esc(id) + "</code> ";
    h += "</p>\n";
  }
  h += "<div class=\"wide\"><table>\n<tr><th class=\"text\">configuration</th><th>frame time A "
       "-&gt; B</th>"
       "<th>values moved</th><th class=\"text\">largest move</th><th "
       "class=\"text\">frames</th></tr>\n";
  for (const ConfigDiff& d : c.configs) {
    const std::string largest =
        d.moved.empty() ? "-" : d.moved.front().name + " " + change_text(d.moved.front());
    const std::string id =
        d.different() ? "<a href=\"#" + anchor(d.id) + "\">" + esc(d.id) + "</a>" : esc(d.id);
    h += std::string("<tr") + (d.different() ? " class=\"moved\"" : "") + "><td class=\"text\">" +
         id + "</td><td>" + esc(frame_time_text(d)) + "</td><td>" + std::to_string(d.moved.size()) +
         "</td><td class=\"text\">" + esc(largest) + "</td><td class=\"text\">" +
         esc(d.image ? image_verdict_short(*d.image) : "no frames kept") + "</td></tr>\n";
  }
  h += "</table></div>\n";
  for (const ConfigDiff& d : c.configs) {
    if (!d.different()) continue;
    h += "<h3 id=\"" + anchor(d.id) + "\">" + esc(d.id) + "</h3>\n" + moved_table(d);
    if (d.image && !d.image->identical) h += image_section(c, *d.image);
  }
  return h;
}

}  // namespace

std::string compare_page_html(const Comparison& c) {
  std::string page = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  page += "<title>skinsim compare</title>\n<style>" + std::string(kPageStyle) + kStyle +
          kImageCompareStyle + "</style>\n</head>\n<body>\n<h1>skinsim compare: " + esc(c.kind) +
          " A against " + esc(c.kind) + " B</h1>\n";
  page += summary(c) + changes_section(c);
  page += c.kind == "run" ? run_sections(c) : sweep_sections(c);
  page += "<h2>How frames are judged</h2>\n<p>" +
          esc("B's frame is compared with A's by FLIP (8-bit frames as stored). " +
              visibility_rule_text(
                  "the pixels its verdict names (the whole frame, or A's reference skin)")) +
          " Crops show the windows of the FLIP error where they differ most; click any image "
          "for full size.</p>\n";
  page +=
      "<h2>Data</h2>\n<p><a href=\"compare.json\">compare.json</a> (everything on this "
      "page).</p>\n";
  page += image_compare_script() + "</body>\n</html>\n";
  return page;
}

void write_compare_files(const Comparison& c, const std::filesystem::path& dir) {
  io::write_file_atomically(dir / "compare.html", compare_page_html(c));
  io::write_file_atomically(dir / "compare.json", nlohmann::json(c).dump(2) + "\n");
}

}  // namespace skinsim::reports
