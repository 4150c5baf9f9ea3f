// Forming the groups of report --compare (docs/usage.md, "Reports and comparisons"): every --by key
// must be a setting of some run, and a group that pools more than seeds (several experiments, or
// runs that differ in a setting other than a seed) says so.
#pragma once

#include <string>
#include <vector>

#include "report/run_comparison.hpp"
#include "report/run_summaries.hpp"

namespace corrmp {

/// Throws ComparisonError unless every key is a setting of some run (a key none has would put
/// every run in one "(unset)" group); the message suggests a close key.
void check_group_keys(const std::vector<RunSummary>& runs, const std::vector<std::string>& keys);

/// Sets group.experiments and group.differing (RunGroup) from the group's runs.
void find_pooling(RunGroup& group, const std::vector<const RunSummary*>& runs,
                  const std::vector<std::string>& group_by);

}  // namespace corrmp
