// Measured per-pass GPU times a user brings to `skinsim validate` (docs/validation.md): a CSV
// of `pass,ms` rows, `#` comments and blank lines ignored, an optional `pass,ms` header, and
// an optional `frame` row for the whole frame's measured time.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "util/user_error.h"

namespace skinsim::driver {

// A measurement file that cannot be used: the message names the file, line and field.
class MeasurementError : public UserError {
 public:
  using UserError::UserError;
};

// The row name that holds the whole frame's measured time (not a pass).
inline constexpr std::string_view kFrameRow = "frame";

struct MeasuredTime {
  std::string name;  // a pass as skinsim names it, or kFrameRow
  double ms = 0.0;   // finite, >= 0
  int line = 0;      // 1-based line in the file
};

struct Measurements {
  std::string file;                   // as named in messages
  std::vector<MeasuredTime> passes;   // in file order, names unique, never kFrameRow
  std::optional<MeasuredTime> frame;  // the `frame` row, when there is one
};

// Parses the CSV text. Each data line is `NAME,MS`: NAME a pass name (letters, digits, '_',
// '-', '.'), MS a plain decimal number of milliseconds >= 0 (skinsim::parse_real: no "nan",
// "inf" or hex). Spaces and tabs around a field and a trailing CR are ignored. Throws
// MeasurementError "FILE:LINE: field 'F': ..." for a bad number, a negative time, a missing or
// extra field, a bad or duplicate name, a quoted field, a misplaced header; and "FILE: ..."
// when the file holds no measurement at all.
Measurements parse_measurements(std::string_view text, const std::string& file_name);

// Reads `path` with io::read_regular_file (io::InputError when missing, a directory, a FIFO or
// too large) and parses it.
Measurements read_measurements(const std::filesystem::path& path);

}  // namespace skinsim::driver
