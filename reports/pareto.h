// Cost/quality trade-off analysis: which configurations are worth considering at all (the
// Pareto front of frame time vs a quality metric) and which one to recommend (the knee).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "results/sweep_table.h"

namespace skinsim::reports {

// Indices into `rows` of the configurations no other row beats on both cost (frame time, or
// another lower-is-better member such as energy_mj) and quality[metric] (direction given by
// higher_is_better); a row dominated by another has both no better and one strictly worse.
// Rows without the metric are left out. Sorted by cost ascending (ties: by index).
std::vector<std::size_t> pareto_front(
    const std::vector<results::ConfigResult>& rows, const std::string& metric,
    bool higher_is_better, double results::ConfigResult::*cost = &results::ConfigResult::frame_ms);

// The recommended configuration: among Pareto-front rows within budget_ms, the one nearest
// the utopia point (cheapest frame time AND best quality of those rows) after normalising
// both axes to [0, 1] over those rows (Euclidean distance). Both axes count equally, so the
// knee is where spending more time stops buying proportionate quality. Ties: lower frame
// time, then lower index. nullopt if no row with the metric fits the budget.
std::optional<std::size_t> pareto_knee(const std::vector<results::ConfigResult>& rows,
                                       const std::string& metric, bool higher_is_better,
                                       double budget_ms);

// One sentence, for the report, saying how pareto_knee chooses.
std::string knee_rule_text();

}  // namespace skinsim::reports
