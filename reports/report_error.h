// The one exception type the reports module throws for user-facing errors (bad results.json,
// unwritable output directory, no X display for charts). Messages name the file/field at fault.
#pragma once

#include <stdexcept>
#include <string>

namespace skinsim::reports {

class ReportError : public std::runtime_error {
 public:
  explicit ReportError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace skinsim::reports
