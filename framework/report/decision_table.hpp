// Each run's decisions as its trials recorded them (the paper's Table I, read from the database):
// per expected decision, in the order the run's task declared its labels, how many trials
// expected it, what the policy chose, the decision match and the task success. Labels come from
// the run's stored task declaration; a run recorded before tasks were stored lists the expected
// decisions of its trials, first seen first.
#pragma once

#include <string>
#include <vector>

#include "report/run_summaries.hpp"

namespace corrmp {

// "| run | experiment | expected | trials | action choice | decision match | task success |";
// runs without decisions have no rows. The decision match is "-" for a run whose policy does not
// decide (it recorded no decision_match_rate).
std::string decision_markdown(const std::vector<RunSummary>& runs);
// run,experiment,expected,trials,chosen,matched,successes; chosen as "2 push; 1 none".
std::string decision_csv(const std::vector<RunSummary>& runs);

}  // namespace corrmp
