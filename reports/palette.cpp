#include "reports/palette.h"

#include <fmt/format.h>

#include <algorithm>

#include "results/pass_rows.h"

namespace skinsim::reports {

Rgb palette_colour(std::size_t i) {
  // Tableau 10 (Tableau Software's default categorical palette): distinct, colour-blind aware.
  static constexpr Rgb kPalette[] = {
      {78, 121, 167}, {242, 142, 43},  {225, 87, 89},   {118, 183, 178}, {89, 161, 79},
      {237, 201, 72}, {176, 122, 161}, {255, 157, 167}, {156, 117, 95},  {186, 176, 172}};
  return kPalette[i % std::size(kPalette)];
}

std::vector<std::string> pass_order(const results::SweepTable& table) {
  std::vector<std::string> names;
  for (const results::ConfigResult& r : table.rows) {
    for (const results::PassCost& p : r.passes) {
      if (std::find(names.begin(), names.end(), p.name) == names.end()) names.push_back(p.name);
    }
  }
  return names;
}

Rgb pass_colour(const std::string& pass, const std::vector<std::string>& order) {
  if (pass == results::kDramWaitRow) return {128, 128, 128};
  const auto it = std::find(order.begin(), order.end(), pass);
  return palette_colour(static_cast<std::size_t>(it - order.begin()));
}

std::string css_colour(const Rgb& c) {
  return fmt::format("#{:02x}{:02x}{:02x}", c[0], c[1], c[2]);
}

}  // namespace skinsim::reports
