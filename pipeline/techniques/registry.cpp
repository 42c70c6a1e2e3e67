// The registry: every technique, one line each. A new technique is a folder under
// pipeline/techniques/ whose .cpp defines NAME_technique() (a TechniqueSpec: its passes,
// programs and own knobs), and a line here.
#include "pipeline/technique.h"

namespace skinsim::pipeline {

const TechniqueSpec& mobile_technique();         // techniques/mobile/
const TechniqueSpec& lod_technique();            // techniques/lod/
const TechniqueSpec& preintegrated_technique();  // techniques/preintegrated/
const TechniqueSpec& wrap_technique();           // techniques/wrap/
const TechniqueSpec& burley_technique();         // techniques/burley/
const TechniqueSpec& ssss_technique();           // techniques/ssss/
const TechniqueSpec& texture_space_technique();  // techniques/texture_space/
const TechniqueSpec& dipole_technique();         // techniques/dipole/
const TechniqueSpec& urp_technique();            // techniques/urp/

const std::vector<const TechniqueSpec*>& all_techniques() {
  static const std::vector<const TechniqueSpec*> all = {
      &mobile_technique(),        &lod_technique(),    &preintegrated_technique(),
      &wrap_technique(),          &burley_technique(), &ssss_technique(),
      &texture_space_technique(), &dipole_technique(), &urp_technique(),
  };
  return all;
}

}  // namespace skinsim::pipeline
