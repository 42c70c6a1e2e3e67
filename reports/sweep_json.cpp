#include "reports/sweep_json.h"

#include <nlohmann/json.hpp>

#include "io/atomic_file.h"
#include "reports/knob_verdicts.h"

namespace skinsim::reports {

void write_sweep_json(const results::SweepTable& table, const std::string& path) {
  results::validate_sweep_table(table);
  nlohmann::json j = table;
  j["findings"] = findings_json(table);  // derived from the rows: read_sweep_json skips it
  io::write_file_atomically(path, j.dump(2) + "\n");
}

}  // namespace skinsim::reports
