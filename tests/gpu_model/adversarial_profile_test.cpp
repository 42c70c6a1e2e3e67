// Adversarial device profiles: every figure of the spec table, broken in every way a file can
// break it, must end as a ProfileError naming the dotted field; nothing else may escape.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "gpu_model/device_profile.h"
#include "gpu_model/error.h"
#include "gpu_model/profile_loader.h"
#include "test_support.h"

namespace skinsim::gpu_model {
namespace {

using testing::kDataDir;

toml::table shipped_table() {
  return toml::parse_file(kDataDir + "/devices/ipad4.toml");
}

std::string to_text(const toml::table& root) {
  std::ostringstream s;
  s << root;
  return s.str();
}

toml::table& figure_table(toml::table& root, const std::string& path) {
  const auto dot = path.find('.');
  return *root[path.substr(0, dot)][path.substr(dot + 1)].as_table();
}

// Loads the text; returns the ProfileError message, or "" when it loaded. Any other
// exception fails the test.
std::string load_error(const std::string& text) {
  try {
    parse_device_profile(text, "adversarial.toml");
  } catch (const ProfileError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not a ProfileError: " << e.what();
  }
  return "";
}

bool accepted_by(const FigureBounds& b, double v) {
  if (!(v >= b.min && v <= b.max)) return false;
  if (b.integer && v != std::floor(v)) return false;
  const auto i = static_cast<long long>(v);
  return !b.power_of_two || (i > 0 && (i & (i - 1)) == 0);
}

// Values no figure may take, and those just outside the figure's bounds.
std::vector<double> bad_values(const FigureBounds& b) {
  const double inf = std::numeric_limits<double>::infinity();
  const double step_below = b.integer ? 1.0 : std::max(std::abs(b.min) * 1e-3, 1e-6);
  const double step_above = b.integer ? 1.0 : std::max(std::abs(b.max) * 1e-3, 1e-6);
  std::vector<double> values = {std::nan(""),
                                inf,
                                -inf,
                                -1.0,
                                0.0,
                                b.min - step_below,
                                b.max + step_above,
                                2147483648.0,
                                9.223372036854775808e18,
                                1e300,
                                1e-300};
  if (b.integer) values.push_back((b.min + b.max) / 2 + 0.5);  // between two integers
  std::vector<double> out;
  for (double v : values) {
    if (!accepted_by(b, v)) out.push_back(v);
  }
  return out;
}

// Stores v as an integer when it is one that TOML can hold, else as a float.
void assign_number(toml::table& t, const std::string& key, double v) {
  if (std::isfinite(v) && v == std::floor(v) && std::abs(v) < 9.2e18) {
    t.insert_or_assign(key, static_cast<std::int64_t>(v));
  } else {
    t.insert_or_assign(key, v);
  }
}

// Gives the figure the range [value, value] with endpoint `end` replaced by v.
void set_range_endpoint(toml::table& f, std::size_t end, double v) {
  toml::table holder;
  assign_number(holder, "x", v);
  toml::array range{*f["value"].node(), *f["value"].node()};
  range.replace(range.begin() + static_cast<std::ptrdiff_t>(end), *holder["x"].node());
  f.insert_or_assign("range", range);
}

struct Mutation {
  std::string name;
  std::string field_suffix;  // appended to the figure's path in the expected message
  std::function<void(toml::table& figure)> apply;
};

std::vector<Mutation> mutations_of(const FigureSpec& spec) {
  const FigureBounds b = spec.bounds;
  std::vector<Mutation> m;
  m.push_back(
      {"value as a string", ".value", [](toml::table& f) { f.insert_or_assign("value", "fast"); }});
  m.push_back({"value as an array", ".value", [](toml::table& f) {
                 f.insert_or_assign("value", toml::array{1, 2});
               }});
  m.push_back({"value missing", ".value", [](toml::table& f) { f.erase("value"); }});
  m.push_back({"unknown key", ".colour", [](toml::table& f) { f.insert_or_assign("colour", 1); }});
  m.push_back(
      {"range not an array", ".range", [](toml::table& f) { f.insert_or_assign("range", 3); }});
  m.push_back({"range of three", ".range", [](toml::table& f) {
                 f.insert_or_assign("range", toml::array{1, 2, 3});
               }});
  // Inverted: [max, min] of the bounds, both endpoints valid, cannot contain the value.
  m.push_back({"range inverted", ".range", [b](toml::table& f) {
                 f.insert_or_assign("range", toml::array{b.max, b.min});
               }});
  for (double bad : bad_values(b)) {
    const std::string label = fmt::format("{}", bad);
    m.push_back(
        {"value " + label, ".value", [bad](toml::table& f) { assign_number(f, "value", bad); }});
    for (std::size_t end : {0, 1}) {
      m.push_back({fmt::format("range[{}] {}", end, label), ".range",
                   [bad, end](toml::table& f) { set_range_endpoint(f, end, bad); }});
    }
  }
  return m;
}

TEST(AdversarialProfile, EveryBrokenFigureIsAProfileErrorNamingTheField) {
  for (const FigureSpec& spec : figure_specs()) {
    for (const Mutation& mutation : mutations_of(spec)) {
      toml::table root = shipped_table();
      mutation.apply(figure_table(root, spec.path));
      const std::string m = load_error(to_text(root));
      const std::string field = "field '" + std::string(spec.path) + mutation.field_suffix;
      EXPECT_NE(m.find(field), std::string::npos)
          << spec.path << ", " << mutation.name << ": " << (m.empty() ? "(accepted)" : m);
    }
  }
}

TEST(AdversarialProfile, OutOfBoundsMessageGivesValueAndAcceptedRange) {
  toml::table root = shipped_table();
  figure_table(root, "gpu.cores").insert_or_assign("value", 65);
  EXPECT_NE(load_error(to_text(root))
                .find("field 'gpu.cores.value': must be an integer in [1, 64] cores, got 65"),
            std::string::npos);
  for (int tile : {1, 257, 4096}) {
    root = shipped_table();
    figure_table(root, "tile.width").insert_or_assign("value", tile);
    figure_table(root, "tile.height").insert_or_assign("value", tile);
    EXPECT_NE(load_error(to_text(root))
                  .find(fmt::format("field 'tile.width.value': must be an integer in [4, 256] px, "
                                    "got {}",
                                    tile)),
              std::string::npos)
        << tile;
  }
  root = shipped_table();
  figure_table(root, "gpu.clock_mhz").insert_or_assign("value", 1e-300);
  figure_table(root, "gpu.clock_mhz").insert_or_assign("range", toml::array{1e-300, 300.0});
  EXPECT_NE(load_error(to_text(root))
                .find("'gpu.clock_mhz.value': must be a number in [1, 10000] "
                      "MHz, got 1e-300"),
            std::string::npos);
}

TEST(AdversarialProfile, EveryFigureIsRequired) {
  for (const FigureSpec& spec : figure_specs()) {
    toml::table root = shipped_table();
    const std::string path = spec.path;
    root[path.substr(0, path.find('.'))].as_table()->erase(path.substr(path.find('.') + 1));
    EXPECT_NE(load_error(to_text(root)).find("field '" + path + "': missing"), std::string::npos)
        << path;
  }
}

TEST(AdversarialProfile, RangesTheEmulatorCannotRunAreRefused) {
  struct Case {
    const char* figure;
    toml::array range;
    const char* field;
    const char* reason;
  };
  const std::vector<Case> cases = {
      {"texture.cache_ways", toml::array{3, 4}, "texture.cache_ways.range[0]", "multiple"},
      {"texture.cache_line_bytes", toml::array{48, 64}, "texture.cache_line_bytes.range[0]",
       "power of two"},
      {"texture.cache_bytes", toml::array{8192, 10000}, "texture.cache_bytes.range[1]", "multiple"},
      {"tile.width", toml::array{16, 32}, "tile.width.range", "square tiles"},
  };
  for (const Case& c : cases) {
    toml::table root = shipped_table();
    figure_table(root, c.figure).insert_or_assign("range", c.range);
    const std::string m = load_error(to_text(root));
    EXPECT_NE(m.find(std::string("field '") + c.field + "'"), std::string::npos) << m;
    EXPECT_NE(m.find(c.reason), std::string::npos) << m;
  }
  // With hashing on, the 6144 B endpoint has 24 sets, which XOR folding cannot index.
  toml::table root = shipped_table();
  figure_table(root, "texture.cache_set_hash").insert_or_assign("value", 1);
  figure_table(root, "texture.cache_bytes").insert_or_assign("range", toml::array{6144, 8192});
  const std::string m = load_error(to_text(root));
  EXPECT_NE(m.find("field 'texture.cache_bytes.range[0]': XOR-folded set index"), std::string::npos)
      << m;
  EXPECT_NE(m.find("= 24 sets"), std::string::npos) << m;
}

TEST(AdversarialProfile, TextLevelBreakagesAreProfileErrors) {
  const std::string text = to_text(shipped_table());
  const std::vector<std::pair<std::string, std::string>> cases = {
      // Duplicate table: TOML forbids it; the parser names the table.
      {text + "\n[gpu.clock_mhz]\nvalue = 1.0\n", "gpu.clock_mhz"},
      // 2^63 does not fit TOML's 64-bit integers: a syntax error at its line.
      {text + "\n[gpu.extra]\nvalue = 9223372036854775808\n", "TOML syntax error"},
      {text + "\n[bogus]\nx = 1\n", "field 'bogus': unknown key"},
      {text + "\n[gpu.clock_ghz]\nvalue = 1.0\n", "field 'gpu.clock_ghz': unknown key"},
  };
  for (const auto& [broken, expected] : cases) {
    const std::string m = load_error(broken);
    EXPECT_NE(m.find(expected), std::string::npos) << expected << ": " << m;
  }
}

TEST(AdversarialProfile, IntegerBoundsFitTheEmulatorsInt) {
  for (const FigureSpec& spec : figure_specs()) {
    if (!spec.bounds.integer) continue;
    EXPECT_LE(spec.bounds.max, static_cast<double>(INT_MAX)) << spec.path;
    EXPECT_GE(spec.bounds.min, 0.0) << spec.path;
  }
}

}  // namespace
}  // namespace skinsim::gpu_model
