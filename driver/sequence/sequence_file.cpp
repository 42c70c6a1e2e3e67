// Sequence files (docs/sequences.md):
//
//   [sequence]
//   preset = "push-in"      # or tracks of its own:
//   name = "slow-orbit"     # [[sequence.track]] knob = "light_azimuth_deg", by = 180
//   frames = 90             #                    (or from = ..., to = ...)
//   fps = 30
//   loops = false
#include <fmt/format.h>
#include <toml++/toml.h>

#include <cmath>
#include <cstdint>

#include "driver/sequence/sequence.h"

namespace skinsim::driver {

namespace {

std::string where(const std::string& file, const toml::node& node, const std::string& key) {
  return fmt::format("{}:{}: {}", file, node.source().begin.line, key);
}

double number(const toml::node& node, const std::string& at) {
  if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
  if (const auto* f = node.as_floating_point(); f && std::isfinite(f->get())) return f->get();
  throw SequenceError(at + ": expected a finite number");
}

SequenceTrack parse_track(const toml::table& table, const std::string& file, int line) {
  SequenceTrack t;
  bool has_from = false, has_to = false, has_by = false;
  for (const auto& [key, node] : table) {
    const std::string k(key.str());
    const std::string at = where(file, node, "sequence.track." + k);
    if (k == "knob") {
      const auto* s = node.as_string();
      if (!s) throw SequenceError(at + ": expected a knob name (a string)");
      t.knob = s->get();
    } else if (k == "from") {
      t.from = number(node, at);
      has_from = true;
    } else if (k == "to") {
      t.to = number(node, at);
      has_to = true;
    } else if (k == "by") {
      t.by = number(node, at);
      has_by = true;
    } else {
      throw SequenceError(at + ": unknown key (expected knob, from, to or by)");
    }
  }
  const std::string at = fmt::format("{}:{}: [[sequence.track]]", file, line);
  if (t.knob.empty()) throw SequenceError(at + ": no knob");
  if (has_by == (has_from || has_to) || (!has_by && !(has_from && has_to))) {
    throw SequenceError(at + " '" + t.knob + "': give either from and to, or by");
  }
  t.relative = has_by;
  return t;
}

}  // namespace

Sequence parse_sequence_file(const std::string& text, const std::filesystem::path& path) {
  const std::string file = path.string();
  toml::table root;
  try {
    root = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw SequenceError(fmt::format("{}:{}:{}: {}", file, e.source().begin.line,
                                    e.source().begin.column, e.description()));
  }
  const toml::table* table = root["sequence"].as_table();
  if (!table) throw SequenceError(file + ": no [sequence] table");
  for (const auto& [key, node] : root) {
    if (key.str() != "sequence") {
      throw SequenceError(where(file, node, std::string(key.str())) + ": unknown key");
    }
  }
  Sequence s;
  s.name = path.stem().string();
  if (const auto* p = (*table)["preset"].as_string()) {
    if (table->contains("track")) {
      throw SequenceError(where(file, *table->get("track"), "sequence.track") +
                          ": a sequence has a preset or tracks, not both");
    }
    try {
      s = load_sequence(p->get(), 0, 0.0);
    } catch (const SequenceError& e) {
      throw SequenceError(where(file, *table->get("preset"), "sequence.preset") + ": " + e.what());
    }
  }
  for (const auto& [key, node] : *table) {
    const std::string k(key.str());
    const std::string at = where(file, node, "sequence." + k);
    if (k == "preset") {
      if (!node.is_string()) throw SequenceError(at + ": expected a preset name (a string)");
    } else if (k == "name") {
      const auto* n = node.as_string();
      if (!n || n->get().empty()) throw SequenceError(at + ": expected a non-empty string");
      s.name = n->get();
    } else if (k == "frames") {
      const auto* i = node.as_integer();
      if (!i || i->get() < 1 || i->get() > kMaxSequenceFrames) {
        throw SequenceError(
            fmt::format("{}: expected an integer in [1, {}]", at, kMaxSequenceFrames));
      }
      s.frames = static_cast<int>(i->get());
    } else if (k == "fps") {
      s.fps = number(node, at);
      if (!(s.fps > 0.0 && s.fps <= 1000.0)) throw SequenceError(at + ": must be in (0, 1000]");
    } else if (k == "loops") {
      const auto* b = node.as_boolean();
      if (!b) throw SequenceError(at + ": expected true or false");
      s.loops = b->get();
    } else if (k == "track") {
      const auto* tracks = node.as_array();
      if (!tracks || !tracks->is_array_of_tables()) {
        throw SequenceError(at + ": expected [[sequence.track]] tables");
      }
      for (const toml::node& t : *tracks) {
        s.tracks.push_back(parse_track(*t.as_table(), file, t.source().begin.line));
      }
    } else {
      throw SequenceError(at +
                          ": unknown key (expected preset, name, frames, fps, loops or track)");
    }
  }
  if (s.tracks.empty()) throw SequenceError(file + ": [sequence] has neither a preset nor tracks");
  if (s.frames < 1) throw SequenceError(file + ": [sequence] needs frames");
  if (!(s.fps > 0.0)) throw SequenceError(file + ": [sequence] needs fps");
  return s;
}

}  // namespace skinsim::driver
