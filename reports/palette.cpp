#include "reports/palette.h"

#include <fmt/format.h>

#include <algorithm>

#include "results/pass_rows.h"

namespace skinsim::reports {

namespace {

constexpr std::size_t kTableau10Size = 10;
constexpr Rgb kDramWaitGrey = {128, 128, 128};

}  // namespace

Rgb palette_colour(std::size_t i) {
  // Tableau 10 (Tableau Software's default categorical palette): distinct, colour-blind aware.
  static constexpr Rgb kPalette[kTableau10Size] = {
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
  if (pass == results::kDramWaitRow) return kDramWaitGrey;
  // Index among the coloured passes: the grey DRAM wait takes no colour of the palette.
  std::size_t index = 0, coloured = 0;
  bool found = false;
  for (const std::string& name : order) {
    if (name == results::kDramWaitRow) continue;
    if (name == pass) found = true;
    if (!found) ++index;
    ++coloured;
  }
  if (coloured <= kTableau10Size) return palette_colour(index);
  // More passes than Tableau 10 has colours (a --techniques sweep has 25): "A Colour
  // Alphabet" (P. Green-Armytage, 2010), 26 colours chosen to be told apart, less its grey
  // (the DRAM wait's).
  static constexpr Rgb kAlphabet[] = {
      {240, 163, 255}, {0, 117, 220}, {153, 63, 0},    {76, 0, 92},     {25, 25, 25},
      {0, 92, 49},     {43, 206, 72}, {255, 204, 153}, {148, 255, 181}, {143, 124, 0},
      {157, 204, 0},   {194, 0, 136}, {0, 51, 128},    {255, 164, 5},   {255, 168, 187},
      {66, 102, 0},    {255, 0, 16},  {94, 241, 242},  {0, 153, 143},   {224, 255, 102},
      {116, 10, 255},  {153, 0, 0},   {255, 255, 128}, {255, 225, 0},   {255, 80, 5}};
  return kAlphabet[index % std::size(kAlphabet)];
}

std::string css_colour(const Rgb& c) {
  return fmt::format("#{:02x}{:02x}{:02x}", c[0], c[1], c[2]);
}

}  // namespace skinsim::reports
