// JUnit XML for CI dashboards: one <testsuite> per budget, one <testcase> per limit line,
// a <failure> with the explanation for each exceeded limit.
#pragma once

#include <string>
#include <string_view>

#include "budget/check.h"

namespace skinsim::budget {

// `suite_name` labels the whole run (e.g. the budget file's path).
std::string junit_xml(const CheckReport& report, const std::string& suite_name);

}  // namespace skinsim::budget
