// Forming report --compare's groups (comparison_groups.hpp).
#include "report/comparison_groups.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

#include "core/config/did_you_mean.hpp"

namespace corrmp {

namespace {

// The keys, other than seeds and `excluded`, whose values differ between
// `runs` (all of one experiment); a key some runs lack differs too.
std::set<std::string> differing_keys(const std::vector<const RunSummary*>& runs,
                                     const std::vector<std::string>& excluded) {
  std::set<std::string> keys;
  for (const auto* run : runs) {
    for (const auto& entry : run->axes) keys.insert(entry.first);
    for (const auto& entry : run->settings) keys.insert(entry.first);
  }
  std::set<std::string> differing;
  for (const auto& key : keys) {
    if (is_seed_key(key) || std::find(excluded.begin(), excluded.end(), key) != excluded.end()) {
      continue;
    }
    const auto first = run_setting(*runs.front(), key);
    const bool differs = std::any_of(runs.begin(), runs.end(), [&](const RunSummary* run) {
      return run_setting(*run, key) != first;
    });
    if (differs) differing.insert(key);
  }
  return differing;
}

}  // namespace

// Every group_by key must be a setting of some run: a key none has would put
// every run in one "(unset)" group. The error suggests a close key.
void check_group_keys(const std::vector<RunSummary>& runs, const std::vector<std::string>& keys) {
  for (const auto& key : keys) {
    const bool found = std::any_of(runs.begin(), runs.end(), [&](const RunSummary& run) {
      return run_setting(run, key).has_value();
    });
    if (found) continue;
    std::set<std::string> known{"experiment"};
    for (const auto& run : runs) {
      for (const auto& entry : run.axes) known.insert(entry.first);
      for (const auto& entry : run.settings) known.insert(entry.first);
    }
    std::vector<std::string> candidates(known.begin(), known.end());
    std::string hint = did_you_mean(key, candidates);
    if (hint.empty()) {  // "updates" for "policy.training.updates"
      const auto suffix = std::find_if(candidates.begin(), candidates.end(), [&](const auto& c) {
        return c.size() > key.size() && c.compare(c.size() - key.size(), key.size(), key) == 0 &&
               c[c.size() - key.size() - 1] == '.';
      });
      if (suffix != candidates.end()) hint = " (did you mean '" + *suffix + "'?)";
    }
    throw ComparisonError(fmt::format("--by '{}': no selected run has this setting{}", key, hint));
  }
}

// What `group` pools besides seeds (RunGroup::experiments, ::differing).
void find_pooling(RunGroup& group, const std::vector<const RunSummary*>& runs,
                  const std::vector<std::string>& group_by) {
  std::map<std::string, std::vector<const RunSummary*>> by_experiment;
  for (const auto* run : runs) {
    if (!by_experiment.count(run->experiment)) group.experiments.push_back(run->experiment);
    by_experiment[run->experiment].push_back(run);
  }
  std::set<std::string> differing;
  for (const auto& entry : by_experiment) {
    const auto keys = differing_keys(entry.second, group_by);
    differing.insert(keys.begin(), keys.end());
  }
  group.differing.assign(differing.begin(), differing.end());
}

}  // namespace corrmp
