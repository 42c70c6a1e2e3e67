// Rows of the knob table (knob.h) for the common kinds of value, each bound to a field of
// PipelineConfig or of a technique's parameter struct nested in it: the parsing, printing and
// range messages are written once here.
#pragma once

#include <functional>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <type_traits>

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

// Where a row's value lives: a field of PipelineConfig (&PipelineConfig::msaa), or a field of
// a technique's parameters nested in it ({&PipelineConfig::dipole, &DipoleParams::samples}).
template <class T>
class ConfigField {
 public:
  ConfigField(T PipelineConfig::*field)  // implicit: a row names a top-level field plainly
      : ref_([field](PipelineConfig& c) -> T& { return c.*field; }),
        cref_([field](const PipelineConfig& c) -> const T& { return c.*field; }) {}
  template <class Params>
  ConfigField(Params PipelineConfig::*params, T Params::*field)
      : ref_([=](PipelineConfig& c) -> T& { return c.*params.*field; }),
        cref_([=](const PipelineConfig& c) -> const T& { return c.*params.*field; }) {}
  T& operator()(PipelineConfig& c) const { return ref_(c); }
  const T& operator()(const PipelineConfig& c) const { return cref_(c); }

 private:
  std::function<T&(PipelineConfig&)> ref_;
  std::function<const T&(const PipelineConfig&)> cref_;
};

// Parsers shared by the rows: plain decimal only (util/parse_number.h); the messages name
// `key`.
float parse_knob_float(const std::string& key, const std::string& text);
int parse_knob_int(const std::string& key, const std::string& text);
glm::vec3 parse_knob_rgb(const std::string& key, const std::string& text);

// A number in `range`.
KnobSpec real_knob(std::string name, std::string flag, std::string help, ConfigField<float> field,
                   Interval range);
// A number in `range`, or "auto" (empty: the pipeline derives it; `help` says how).
KnobSpec optional_real_knob(std::string name, std::string flag, std::string help,
                            ConfigField<std::optional<float>> field, Interval range);
// An integer in [lo, hi], a power of two when `power_of_two`.
KnobSpec integer_knob(std::string name, std::string flag, std::string help, ConfigField<int> field,
                      int lo, int hi, bool power_of_two = false);
// The row with KnobSpec::reference set.
KnobSpec shapes_reference(KnobSpec knob);
// The row with the sweep's option for it as an axis (KnobSpec::sweep_flag, sweep_help).
KnobSpec swept_by(KnobSpec knob, std::string sweep_flag, std::string sweep_help);
// "on" or "off".
KnobSpec switch_knob(std::string name, std::string flag, std::string help, ConfigField<bool> field);
// "r,g,b", each in `range`, or "auto" (empty; `help` says what that means).
KnobSpec optional_rgb_knob(std::string name, std::string flag, std::string help,
                           ConfigField<std::optional<glm::vec3>> field, Interval range);
// "WxH", each a power of two in [lo, hi].
KnobSpec size_knob(std::string name, std::string flag, std::string help, ConfigField<int> width,
                   ConfigField<int> height, int lo, int hi);
// One of a set of names, through the enum's own parse and name functions.
template <class E>
KnobSpec choice_knob(std::string name, std::string flag, std::string help, std::string values,
                     std::type_identity_t<ConfigField<E>> field, E (*parse)(const std::string&),
                     const char* (*print)(E)) {
  KnobSpec k;
  k.name = std::move(name);
  k.flag = std::move(flag);
  k.values = std::move(values);
  k.help = std::move(help);
  k.set = [field, parse](PipelineConfig& c, const std::string& text) { field(c) = parse(text); };
  k.get = [field, print](const PipelineConfig& c) { return std::string(print(field(c))); };
  k.invalid = [](const PipelineConfig&) { return std::string(); };
  return k;
}

}  // namespace skinsim::pipeline
