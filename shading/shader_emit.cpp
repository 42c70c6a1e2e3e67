#include "shading/shader_emit.h"

#include <cstdio>
#include <cstring>
#include <utility>

namespace skinsim::sim::sl {

std::string GlslEmitter::bind(const std::string& type, const std::string& expr) {
  std::string line;
  if (!current_) return line.append("(").append(expr).append(")");
  std::string name = "t";
  name += std::to_string(current_->next_temp_++);
  line.append(type).append(" ").append(name).append(" = ").append(expr).append(";");
  current_->lines_.push_back(std::move(line));
  return name;
}

void GlslEmitter::statement(const std::string& text) {
  if (current_) current_->lines_.push_back(text);
}

std::string GlslEmitter::body(int indent) const {
  std::string out;
  for (const std::string& line : lines_) {
    out.append(static_cast<size_t>(indent), ' ');
    out += line;
    out += '\n';
  }
  return out;
}

std::string glsl_float(float f) {
  char buffer[32];
  // Shortest precision that reads back to the same float, up to 9 digits.
  for (int digits = 1; digits <= 9; ++digits) {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, static_cast<double>(f));
    if (std::strtof(buffer, nullptr) == f) break;
  }
  std::string s = buffer;
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // "n": nan/inf stay as is
  return s;
}

}  // namespace skinsim::sim::sl
