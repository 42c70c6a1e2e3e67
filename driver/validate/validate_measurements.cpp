#include "driver/validate/validate_measurements.h"

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <unordered_map>

#include "io/read_file.h"
#include "util/parse_number.h"

namespace skinsim::driver {
namespace {

std::string_view trim(std::string_view s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t'; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

bool name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == '.';
}

// A field quoted in a message: printable ASCII as is, anything else as \xNN, at most 40
// characters, so a binary file gives a readable message.
std::string quoted(std::string_view s) {
  std::string out = "'";
  for (std::size_t i = 0; i < s.size() && i < 40; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    out += (c >= 0x20 && c < 0x7f) ? std::string(1, static_cast<char>(c))
                                   : fmt::format("\\x{:02x}", c);
  }
  if (s.size() > 40) out += "...";
  return out + "'";
}

class LineParser {
 public:
  LineParser(std::string file, int line) : file_(std::move(file)), line_(line) {}

  [[noreturn]] void fail(std::string_view field, const std::string& what) const {
    if (field.empty()) throw MeasurementError(fmt::format("{}:{}: {}", file_, line_, what));
    throw MeasurementError(fmt::format("{}:{}: field '{}': {}", file_, line_, field, what));
  }

 private:
  std::string file_;
  int line_;
};

}  // namespace

Measurements parse_measurements(std::string_view text, const std::string& file_name) {
  Measurements m;
  m.file = file_name;
  bool seen_data = false;    // a measurement or the header
  bool seen_header = false;  // the `pass,ms` header
  int line_number = 0;
  std::unordered_map<std::string, int> first_line;  // of each pass (and kFrameRow) measured
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const LineParser at(file_name, line_number);
    if (line.find('\0') != std::string_view::npos) at.fail("", "holds a NUL byte: not a text file");
    line = trim(line);
    if (line.empty() || line.front() == '#') continue;
    if (line.find('"') != std::string_view::npos) {
      at.fail("", "quoted fields are not supported: write NAME,MS without quotes");
    }
    const std::size_t comma = line.find(',');
    if (comma == std::string_view::npos) {
      at.fail("", fmt::format("expected two fields 'pass,ms' separated by a comma, got {}",
                              quoted(line)));
    }
    const std::string_view name = trim(line.substr(0, comma));
    const std::string_view rest = line.substr(comma + 1);
    if (rest.find(',') != std::string_view::npos) {
      at.fail("", fmt::format("expected two fields 'pass,ms', got {} (more than one comma)",
                              quoted(line)));
    }
    const std::string_view ms_text = trim(rest);
    if (name == "pass") {  // the header
      if (ms_text != "ms") {
        at.fail("ms", fmt::format("the header must be 'pass,ms', got {}", quoted(line)));
      }
      if (seen_data) at.fail("pass", "the 'pass,ms' header must come before the measurements");
      seen_data = seen_header = true;
      continue;
    }
    seen_data = true;
    if (name.empty()) at.fail("pass", "is empty");
    if (!std::all_of(name.begin(), name.end(), name_char)) {
      at.fail("pass",
              fmt::format("{} is not a pass name (letters, digits, '_', '-', '.')", quoted(name)));
    }
    if (ms_text.empty()) at.fail("ms", fmt::format("is empty (pass '{}')", name));
    const std::optional<double> ms = parse_real<double>(ms_text);
    if (!ms) {
      at.fail("ms", fmt::format("expected a plain decimal number of milliseconds, got {}",
                                quoted(ms_text)));
    }
    if (*ms < 0.0) {
      at.fail("ms", fmt::format("a time cannot be negative, got {} for pass '{}'",
                                std::string(ms_text), name));
    }
    MeasuredTime t{std::string(name), *ms, line_number};
    // A hash set, not a search of the passes so far: a million-line file is read in linear time.
    if (const auto [earlier, fresh] = first_line.try_emplace(t.name, line_number); !fresh) {
      at.fail("pass", fmt::format("'{}' is measured twice (first on line {}): give each pass "
                                  "one time",
                                  name, earlier->second));
    }
    if (name == kFrameRow) {
      m.frame = std::move(t);
    } else {
      m.passes.push_back(std::move(t));
    }
  }
  if (m.passes.empty() && !m.frame) {
    throw MeasurementError(fmt::format(
        "{}: no measurements{} (expected lines 'pass,ms', e.g. 'skin,12.5', and optionally "
        "'frame,MS'; see docs/validation.md)",
        file_name, seen_header ? " after the header" : ""));
  }
  return m;
}

Measurements read_measurements(const std::filesystem::path& path) {
  return parse_measurements(io::read_regular_file(path, "measurements file"), path.string());
}

}  // namespace skinsim::driver
