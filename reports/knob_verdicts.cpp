#include "reports/knob_verdicts.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include "reports/knob_order.h"
#include "reports/recommendation.h"

namespace skinsim::reports {

namespace {

constexpr const char* kTechnique = "technique";

// A group's rows of one technique, in table order.
using Rows = std::vector<const results::ConfigResult*>;

std::map<std::string, Rows> by_technique(const results::SweepTable& t, const std::string& group) {
  std::map<std::string, Rows> out;
  for (const results::ConfigResult& r : t.rows) {
    if (r.group == group) out[knob_value(r, kTechnique)].push_back(&r);
  }
  return out;
}

// "1,234": pixel counts read at a glance.
std::string count_text(double v) {
  const std::string digits = fmt::format("{:.0f}", v);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    const std::size_t left = digits.size() - i;  // digits from here to the end
    if (i > 0 && left % 3 == 0 && digits[i - 1] != '-') out += ',';
    out += digits[i];
  }
  return out;
}

std::string area_of(const std::string& metric) {
  return metric == "flip_skin" ? "skin" : "the frame";
}

// Knobs with two or more values within some group (a knob only some techniques use counts
// its values where it is used).
std::set<std::string> judged_knobs(const results::SweepTable& t) {
  std::map<std::pair<std::string, std::string>, std::set<std::string>> values;  // (group, knob)
  for (const results::ConfigResult& r : t.rows) {
    for (const auto& [k, v] : r.knobs) values[{r.group, k}].insert(v);
  }
  std::set<std::string> out;
  for (const auto& [key, vs] : values) {
    if (vs.size() > 1) out.insert(key.second);
  }
  return out;
}

// A value as the sentences name it: "lut 8x32", "scale 0.5"; a technique by its name alone.
std::string value_text(const results::ConfigResult& r, const std::string& knob) {
  return knob == kTechnique ? knob_value(r, knob) : knob + " " + knob_value(r, knob);
}

bool same_except(const results::ConfigResult& a, const results::ConfigResult& b,
                 const std::string& knob) {
  std::map<std::string, std::string> ka = a.knobs, kb = b.knobs;
  ka.erase(knob);
  kb.erase(knob);
  return ka == kb;
}

// What the knob's values do to the frame time against `around`'s: the cheapest value's
// saving and the dearest's extra cost, each stated when it is kNoTimeEffect of the frame or
// more; otherwise no time effect.
std::string time_part(const std::vector<const results::ConfigResult*>& slice,
                      const results::ConfigResult& around, const std::string& knob, bool& effect) {
  const auto [lo, hi] =
      std::minmax_element(slice.begin(), slice.end(),
                          [](const results::ConfigResult* a, const results::ConfigResult* b) {
                            return a->frame_ms < b->frame_ms;
                          });
  const double threshold = kNoTimeEffect * around.frame_ms;
  const double saves = around.frame_ms - (*lo)->frame_ms;
  const double costs = (*hi)->frame_ms - around.frame_ms;
  const bool cheaper = saves >= threshold, dearer = costs >= threshold;
  effect = cheaper || dearer;
  const std::string at = value_text(around, knob);
  if (cheaper && dearer) {
    return fmt::format(
        "{} saves {:.2f} ms and {} costs {:.2f} ms more than {} ({:.2f}, {:.2f}, "
        "{:.2f} ms)",
        value_text(**lo, knob), saves, value_text(**hi, knob), costs, at, (*lo)->frame_ms,
        around.frame_ms, (*hi)->frame_ms);
  }
  if (cheaper) {
    return fmt::format("{} saves {:.2f} ms against {} ({:.2f} -> {:.2f} ms)",
                       value_text(**lo, knob), saves, at, around.frame_ms, (*lo)->frame_ms);
  }
  if (dearer) {
    return fmt::format(
        "no value saves time against {}; {} costs {:.2f} ms more ({:.2f} -> "
        "{:.2f} ms)",
        at, value_text(**hi, knob), costs, around.frame_ms, (*hi)->frame_ms);
  }
  return fmt::format("no time effect ({:.2f} to {:.2f} ms over its {} values)", (*lo)->frame_ms,
                     (*hi)->frame_ms, slice.size());
}

// Which values differ visibly from `around`'s, by `comparison` (vs_finest or vs_best).
std::string visible_part(const std::vector<const results::ConfigResult*>& slice,
                         const results::ConfigResult& around, const std::string& knob,
                         std::optional<results::FrameComparison> results::ConfigResult::*comparison,
                         const std::string& metric, bool& effect) {
  std::vector<std::string> visible;
  double largest_invisible = 0.0;
  std::size_t compared = 0;
  for (const results::ConfigResult* r : slice) {
    const auto& c = r->*comparison;
    if (r == &around || !c || c->against != around.id) continue;
    ++compared;
    if (!c->visible) {
      largest_invisible = std::max(largest_invisible, c->visible_px);
      continue;
    }
    visible.push_back(fmt::format("{} on {} px{}", value_text(*r, knob), count_text(c->visible_px),
                                  visible.empty() ? " of " + area_of(metric) : ""));
  }
  effect = !visible.empty();
  const std::string at = value_text(around, knob);
  if (compared == 0) return "its visible effect was not measured (no frames compared)";
  if (visible.empty()) {
    return fmt::format(
        "no value looks different from {} (at most {} px above the visibility "
        "threshold)",
        at, count_text(largest_invisible));
  }
  std::string list = visible.front();
  for (std::size_t i = 1; i < visible.size(); ++i) list += ", " + visible[i];
  return fmt::format("visibly different from {}, the closest to the reference: {}", at, list);
}

std::vector<const results::ConfigResult*> sorted_by_value(
    std::vector<const results::ConfigResult*> rows, const std::string& knob) {
  std::stable_sort(rows.begin(), rows.end(),
                   [&](const results::ConfigResult* a, const results::ConfigResult* b) {
                     return knob_value_less(knob_value(*a, knob), knob_value(*b, knob));
                   });
  return rows;
}

// Each technique's finest row against the group's best: its frame time, and whether it
// looks different (vs_best).
KnobVerdict technique_verdict(const std::string& group, const std::map<std::string, Rows>& techs,
                              const std::string& metric) {
  KnobVerdict v;
  v.group = group;
  v.knob = kTechnique;
  std::vector<const results::ConfigResult*> finest;
  for (const auto& [technique, rows] : techs) {
    if (const results::ConfigResult* f = lowest_metric(rows, metric)) finest.push_back(f);
  }
  const results::ConfigResult* best = lowest_metric(finest, metric);
  if (!best) {
    v.kind = KnobVerdict::Kind::not_isolated;
    v.sentence = "technique: no technique has the quality metric, so none is judged.";
    return v;
  }
  v.around = best->id;
  const double threshold = kNoTimeEffect * best->frame_ms;
  std::string others;
  for (const results::ConfigResult* f : finest) {
    if (f == best) continue;
    const double delta = f->frame_ms - best->frame_ms;
    v.time_effect = v.time_effect || std::abs(delta) >= threshold;
    const std::string time = std::abs(delta) < threshold ? "no time difference"
                             : delta < 0.0               ? fmt::format("saves {:.2f} ms", -delta)
                                           : fmt::format("costs {:.2f} ms more", delta);
    std::string seen = "not compared";
    if (f->vs_best && f->vs_best->against == best->id) {
      v.visible_effect = v.visible_effect || f->vs_best->visible;
      seen = f->vs_best->visible ? fmt::format("visibly different on {} px of {}",
                                               count_text(f->vs_best->visible_px), area_of(metric))
                                 : "looks the same";
    }
    others +=
        fmt::format("; {} {:.2f} ms ({}), {}", knob_value(*f, kTechnique), f->frame_ms, time, seen);
  }
  v.sentence = fmt::format(
      "technique (each at its best knobs): {} is the closest to the reference at {:.2f} ms{}.",
      knob_value(*best, kTechnique), best->frame_ms, others);
  return v;
}

KnobVerdict knob_verdict(const std::string& group, const std::string& technique, const Rows& rows,
                         const results::ConfigResult& around, const std::string& knob,
                         const std::string& metric) {
  KnobVerdict v;
  v.group = group;
  v.technique = technique;
  v.knob = knob;
  v.around = around.id;
  const std::string name = technique.empty() ? knob : fmt::format("{} ({})", knob, technique);
  std::set<std::string> values;
  for (const results::ConfigResult* r : rows) {
    if (r->knobs.count(knob)) values.insert(knob_value(*r, knob));
  }
  if (values.size() == 1) {
    v.kind = KnobVerdict::Kind::one_value;
    v.sentence =
        fmt::format("{}: only {} was swept, so its effect is not measured.", name, *values.begin());
    return v;
  }
  std::vector<const results::ConfigResult*> slice;
  for (const results::ConfigResult* r : rows) {
    if (r->knobs.count(knob) && same_except(*r, around, knob)) slice.push_back(r);
  }
  slice = sorted_by_value(slice, knob);
  if (slice.size() < 2) {
    v.kind = KnobVerdict::Kind::not_isolated;
    v.sentence = fmt::format(
        "{}: no configuration differs from {} in this knob alone, so its effect is not "
        "separated from the other knobs'.",
        name, around.id);
    return v;
  }
  const std::string time = time_part(slice, around, knob, v.time_effect);
  const std::string seen = visible_part(slice, around, knob, &results::ConfigResult::vs_finest,
                                        metric, v.visible_effect);
  v.sentence = fmt::format("{}: {}; {}.", name, time, seen);
  return v;
}

}  // namespace

std::vector<KnobVerdict> knob_verdicts(const results::SweepTable& table,
                                       const std::string& metric) {
  const std::set<std::string> judged = judged_knobs(table);
  std::vector<KnobVerdict> out;
  for (const std::string& group : groups_in_order(table)) {
    const std::map<std::string, Rows> techs = by_technique(table, group);
    if (techs.size() > 1) out.push_back(technique_verdict(group, techs, metric));
    for (const auto& [technique, rows] : techs) {
      const results::ConfigResult* around = lowest_metric(rows, metric);
      if (!around) continue;
      for (const std::string& knob : judged) {
        if (knob == kTechnique || !around->knobs.count(knob)) continue;  // not its knob
        out.push_back(knob_verdict(group, technique, rows, *around, knob, metric));
      }
    }
  }
  return out;
}

std::vector<TechniqueError> technique_errors(const results::SweepTable& table,
                                             const std::string& metric) {
  std::vector<TechniqueError> out;
  for (const std::string& group : groups_in_order(table)) {
    for (const auto& [technique, rows] : by_technique(table, group)) {
      const results::ConfigResult* finest = lowest_metric(rows, metric);
      if (!finest) continue;
      TechniqueError e;
      e.group = group;
      e.technique = technique;
      e.finest = finest->id;
      e.technique_error = finest->quality.at(metric);
      e.configurations = static_cast<int>(rows.size());
      for (const results::ConfigResult* r : rows) {
        if (r == finest || !r->vs_finest || r->vs_finest->against != finest->id) continue;
        e.visibly_worse += r->vs_finest->visible;
        if (e.worst.empty() || r->vs_finest->flip_mean > e.knob_error) {
          e.worst = r->id;
          e.knob_error = r->vs_finest->flip_mean;
          e.knob_visible_px = r->vs_finest->visible_px;
        }
      }
      const std::string who = technique.empty() ? "The technique" : technique;
      e.sentence = fmt::format(
          "{}: {} {:.4f} against the reference at its best knobs ({}), the technique error", who,
          metric, e.technique_error, e.finest);
      if (e.worst.empty()) {
        e.sentence +=
            "; no other knob values were compared with it, so the knob error is not "
            "measured.";
      } else {
        e.sentence += fmt::format(
            "; its other knob values add up to FLIP {:.4f} against that ({}, {} px above the "
            "visibility threshold), the knob error; {} of its {} other configurations differ "
            "visibly from its best.",
            e.knob_error, e.worst, count_text(e.knob_visible_px), e.visibly_worse,
            e.configurations - 1);
      }
      out.push_back(std::move(e));
    }
  }
  return out;
}

std::vector<std::string> unswept_knobs(const results::SweepTable& table) {
  std::map<std::string, std::set<std::string>> values;
  for (const results::ConfigResult& r : table.rows) {
    for (const auto& [k, v] : r.knobs) values[k].insert(v);
  }
  std::vector<std::string> out;
  for (const auto& [k, vs] : values) {
    if (vs.size() == 1) out.push_back(k + "=" + *vs.begin());
  }
  return out;
}

nlohmann::json findings_json(const results::SweepTable& table) {
  const std::string metric = recommend_metric(table.rows);
  nlohmann::json recommendations = nlohmann::json::array();
  for (const Recommendation& r : recommend(table, metric)) {
    recommendations.push_back(recommendation_json(table, r));
  }
  nlohmann::json verdicts = nlohmann::json::array();
  for (const KnobVerdict& v : knob_verdicts(table, metric)) {
    static const char* const kKinds[] = {"one_value", "not_isolated", "measured"};
    verdicts.push_back({{"group", v.group},
                        {"technique", v.technique},
                        {"knob", v.knob},
                        {"around", v.around},
                        {"kind", kKinds[static_cast<int>(v.kind)]},
                        {"time_effect", v.time_effect},
                        {"visible_effect", v.visible_effect},
                        {"sentence", v.sentence}});
  }
  nlohmann::json errors = nlohmann::json::array();
  for (const TechniqueError& e : technique_errors(table, metric)) {
    errors.push_back({{"group", e.group},
                      {"technique", e.technique},
                      {"finest", e.finest},
                      {"technique_error", e.technique_error},
                      {"worst", e.worst},
                      {"knob_error", e.knob_error},
                      {"knob_visible_px", e.knob_visible_px},
                      {"visibly_worse", e.visibly_worse},
                      {"sentence", e.sentence}});
  }
  return {{"metric", metric},
          {"recommendations", recommendations},
          {"knob_verdicts", verdicts},
          {"technique_errors", errors},
          {"unswept_knobs", unswept_knobs(table)}};
}

}  // namespace skinsim::reports
