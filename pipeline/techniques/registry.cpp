// The registry: every technique, in order (the first is the default). A new technique is a
// folder under pipeline/techniques/ whose .cpp defines NAME_technique() (a TechniqueSpec: its
// passes, programs and own knobs), its declaration and its entry here
// (docs/adding-a-technique.md).
#include "pipeline/technique.h"

namespace skinsim::pipeline {

const TechniqueSpec& mobile_technique();
const TechniqueSpec& lod_technique();
const TechniqueSpec& preintegrated_technique();
const TechniqueSpec& wrap_technique();
const TechniqueSpec& burley_technique();
const TechniqueSpec& ssss_technique();
const TechniqueSpec& texture_space_technique();
const TechniqueSpec& dipole_technique();
const TechniqueSpec& urp_technique();

const std::vector<const TechniqueSpec*>& all_techniques() {
  static const std::vector<const TechniqueSpec*> all = {
      &mobile_technique(),         // techniques/mobile/
      &lod_technique(),            // techniques/lod/
      &preintegrated_technique(),  // techniques/preintegrated/
      &wrap_technique(),           // techniques/wrap/
      &burley_technique(),         // techniques/burley/
      &ssss_technique(),           // techniques/ssss/
      &texture_space_technique(),  // techniques/texture_space/
      &dipole_technique(),         // techniques/dipole/
      &urp_technique(),            // techniques/urp/
  };
  return all;
}

}  // namespace skinsim::pipeline
