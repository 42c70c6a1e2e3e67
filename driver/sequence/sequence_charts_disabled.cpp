// write_sequence_charts in a build without VTK (SKINSIM_BUILD_REPORTS=OFF).
#include "driver/sequence/sequence_charts.h"

namespace skinsim::driver {

SequenceChartsOutcome write_sequence_charts(const Sequence&, const SequenceResult&,
                                            const std::string&, const std::filesystem::path&) {
  return {{}, "this skinsim was built without the charts (SKINSIM_BUILD_REPORTS=OFF)", false};
}

}  // namespace skinsim::driver
