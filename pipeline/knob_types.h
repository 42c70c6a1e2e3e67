// Rows of the knob table (knob.h) for the common kinds of value, each bound to a field of
// PipelineConfig: the parsing, printing and range messages are written once here.
#pragma once

#include <glm/vec3.hpp>
#include <optional>
#include <string>

#include "pipeline/config.h"
#include "pipeline/knob.h"

namespace skinsim::pipeline {

// A range as messages write it: "(0, 1]", "[4, 64]".
struct Interval {
  double lo = 0.0;
  double hi = 0.0;
  bool lo_open = false;
  bool hi_open = false;
  bool contains(float v) const;  // compared as floats, the knobs' type; false for NaN
  std::string text() const;
};

// Parsers shared by the rows: plain decimal only (util/parse_number.h); the messages name
// `key`.
float parse_knob_float(const std::string& key, const std::string& text);
int parse_knob_int(const std::string& key, const std::string& text);
glm::vec3 parse_knob_rgb(const std::string& key, const std::string& text);

// A number in `range`.
KnobSpec real_knob(std::string name, std::string flag, std::string help,
                   float PipelineConfig::*field, Interval range);
// A number in `range`, or "auto" (empty: the pipeline derives it; `help` says how).
KnobSpec optional_real_knob(std::string name, std::string flag, std::string help,
                            std::optional<float> PipelineConfig::*field, Interval range);
// An integer in [lo, hi], a power of two when `power_of_two`.
KnobSpec integer_knob(std::string name, std::string flag, std::string help,
                      int PipelineConfig::*field, int lo, int hi, bool power_of_two = false);
// The row with KnobSpec::reference set.
KnobSpec shapes_reference(KnobSpec knob);
// The row with the sweep's option for it as an axis (KnobSpec::sweep_flag, sweep_help).
KnobSpec swept_by(KnobSpec knob, std::string sweep_flag, std::string sweep_help);
// "on" or "off".
KnobSpec switch_knob(std::string name, std::string flag, std::string help,
                     bool PipelineConfig::*field);
// "r,g,b", each in `range`, or "auto" (empty; `help` says what that means).
KnobSpec optional_rgb_knob(std::string name, std::string flag, std::string help,
                           std::optional<glm::vec3> PipelineConfig::*field, Interval range);
// "WxH", each a power of two in [lo, hi].
KnobSpec size_knob(std::string name, std::string flag, std::string help, int PipelineConfig::*width,
                   int PipelineConfig::*height, int lo, int hi);
// One of a set of names, through the enum's own parse and name functions.
template <class E>
KnobSpec choice_knob(std::string name, std::string flag, std::string help, std::string values,
                     E PipelineConfig::*field, E (*parse)(const std::string&),
                     const char* (*print)(E)) {
  KnobSpec k;
  k.name = std::move(name);
  k.flag = std::move(flag);
  k.values = std::move(values);
  k.help = std::move(help);
  k.set = [field, parse](PipelineConfig& c, const std::string& text) { c.*field = parse(text); };
  k.get = [field, print](const PipelineConfig& c) { return std::string(print(c.*field)); };
  k.invalid = [](const PipelineConfig&) { return std::string(); };
  return k;
}

}  // namespace skinsim::pipeline
