#include <fmt/format.h>

#include "microbench/microbench.h"

namespace skinsim::microbench {

std::string format_microbench_table(const std::vector<MicrobenchResult>& results) {
  std::string out = fmt::format("{:<20} {:>10} {:<9} {:>10} {:>7} {:<10} {:>9}\n", "benchmark",
                                "simulated", "unit", "peak", "% peak", "bound by", "pass ms");
  for (const MicrobenchResult& r : results) {
    out +=
        fmt::format("{:<20} {:>10.1f} {:<9} {:>10.1f} {:>6.1f}% {:<10} {:>9.3f}\n", r.name, r.value,
                    r.unit, r.peak, 100.0 * r.ratio, gpu_model::unit_name(r.bottleneck), r.pass_ms);
  }
  out += "\n";
  for (const MicrobenchResult& r : results) {
    out += fmt::format("{}: {}\n  peak = {}\n", r.name, r.shows, r.peak_basis);
  }
  return out;
}

}  // namespace skinsim::microbench
