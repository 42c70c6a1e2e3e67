// The registry: every technique, in order (the first is the default). A new technique is a
// folder under pipeline/techniques/ whose .cpp defines NAME_technique() (a TechniqueSpec: its
// passes, programs and own knobs) and its line in SKINSIM_TECHNIQUES below
// (docs/adding-a-technique.md).
#include "pipeline/technique.h"

// One X(name) per technique folder: declares name_technique() and lists it, so a technique
// is one line here.
#define SKINSIM_TECHNIQUES(X) \
  X(mobile)                   \
  X(lod)                      \
  X(preintegrated)            \
  X(wrap)                     \
  X(burley)                   \
  X(ssss)                     \
  X(texture_space)            \
  X(dipole)                   \
  X(urp)

namespace skinsim::pipeline {

#define SKINSIM_DECLARE_TECHNIQUE(name) const TechniqueSpec& name##_technique();
SKINSIM_TECHNIQUES(SKINSIM_DECLARE_TECHNIQUE)

const std::vector<const TechniqueSpec*>& all_techniques() {
#define SKINSIM_LIST_TECHNIQUE(name) &name##_technique(),
  static const std::vector<const TechniqueSpec*> all = {SKINSIM_TECHNIQUES(SKINSIM_LIST_TECHNIQUE)};
  return all;
}

// The build compiles several files as one unit (SKINSIM_UNITY_BUILD): keep the macros here.
#undef SKINSIM_LIST_TECHNIQUE
#undef SKINSIM_DECLARE_TECHNIQUE
#undef SKINSIM_TECHNIQUES

}  // namespace skinsim::pipeline
