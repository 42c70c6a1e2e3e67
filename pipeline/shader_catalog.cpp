#include "pipeline/shader_catalog.h"

#include <algorithm>

#include "pipeline/shader_variants.h"
#include "pipeline/shaders/background.h"
#include "pipeline/shaders/eye.h"
#include "pipeline/shaders/shadow.h"
#include "pipeline/shaders/surface_vs.h"
#include "pipeline/technique.h"

namespace skinsim::pipeline {

std::vector<CatalogEntry> shader_catalog() {
  std::vector<CatalogEntry> catalog;
  const auto add = [&](const sim::NamedProfile& program, const std::string& technique) {
    auto it = std::find_if(catalog.begin(), catalog.end(),
                           [&](const CatalogEntry& e) { return e.program.name == program.name; });
    if (it == catalog.end()) it = catalog.insert(catalog.end(), {program, {}});
    if (std::find(it->techniques.begin(), it->techniques.end(), technique) ==
        it->techniques.end()) {
      it->techniques.push_back(technique);
    }
  };
  for (const TechniqueSpec* t : all_techniques()) {
    for (const sim::NamedProfile& p :
         {vertex_entry<shaders::ShadowVS>(), vertex_entry<shaders::SurfaceVS>(),
          fragment_entry<shaders::EyeFS>(), fragment_entry<shaders::BackgroundFS>()}) {
      add(p, t->name);
    }
  }
  for (const TechniqueSpec* t : all_techniques()) {
    for (const sim::NamedProfile& p : t->shaders()) add(p, t->name);
  }
  return catalog;
}

}  // namespace skinsim::pipeline
