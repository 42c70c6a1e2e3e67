#include "reports/knob_order.h"

#include <cctype>
#include <cstdlib>
#include <vector>

namespace skinsim::reports {

namespace {

std::vector<double> numbers_in(const std::string& s) {
  std::vector<double> out;
  const char* p = s.c_str();
  while (*p) {
    if (std::isdigit(static_cast<unsigned char>(*p)) ||
        (*p == '.' && std::isdigit(static_cast<unsigned char>(p[1])))) {
      char* end = nullptr;
      out.push_back(std::strtod(p, &end));
      p = end;
    } else {
      ++p;
    }
  }
  return out;
}

}  // namespace

bool knob_value_less(const std::string& a, const std::string& b) {
  const std::vector<double> na = numbers_in(a);
  const std::vector<double> nb = numbers_in(b);
  if (!na.empty() && !nb.empty() && na != nb) return na < nb;
  return a < b;
}

}  // namespace skinsim::reports
