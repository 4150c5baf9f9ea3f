// Declarations of metrics recorded before metrics were declared (legacy_metrics.hpp).
#include "store/legacy_metrics.hpp"

#include <algorithm>
#include <cctype>
#include <set>
#include <sstream>
#include <vector>

namespace corrmp {

namespace {

const std::string kClosedLoopMean = "_mp_error_mean_";  // <segment>_mp_error_mean_<unit>
const std::string kClosedLoopMax = "_mp_error_max_";
const std::string kHeldOutMean = "_error_mean";  // <segment>_error_mean
const std::string kHeldOutMax = "_error_max";

std::vector<std::string> words_of(const std::string& name) {
  std::vector<std::string> words;
  std::stringstream parts(name);
  std::string word;
  while (std::getline(parts, word, '_')) words.push_back(word);
  return words;
}

bool ends_with(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

bool starts_with(const std::string& text, const std::string& start) {
  return text.rfind(start, 0) == 0;
}

// A closed-loop error statistic: <segment><marker><unit>, segment and unit not empty.
bool closed_loop_error(const std::string& name, const std::string& marker, const char* statistic,
                       MetricDeclaration& out) {
  const auto at = name.find(marker);
  if (at == std::string::npos || at == 0) return false;
  const std::string segment = name.substr(0, at), unit = name.substr(at + marker.size());
  if (unit.empty()) return false;
  out = error_statistic(unit, segment + "-MP error mean / max (" + unit + ")", statistic);
  return true;
}

// A held-out error statistic: <segment><suffix>, segment not empty.
bool held_out_error(const std::string& name, const std::string& suffix, const char* statistic,
                    MetricDeclaration& out) {
  if (!ends_with(name, suffix) || name.size() <= suffix.size()) return false;
  const std::string segment = name.substr(0, name.size() - suffix.size());
  out = error_statistic("", segment + " error mean / max (held-out)", statistic);
  return true;
}

}  // namespace

MetricDeclaration inferred_declaration(const std::string& name) {
  MetricDeclaration declaration;
  if (closed_loop_error(name, kClosedLoopMean, "mean", declaration) ||
      closed_loop_error(name, kClosedLoopMax, "max", declaration) ||
      held_out_error(name, kHeldOutMean, "mean", declaration) ||
      held_out_error(name, kHeldOutMax, "max", declaration)) {
    return declaration;
  }
  const std::vector<std::string> list = words_of(name);
  const std::set<std::string> words(list.begin(), list.end());
  if (words.count("rate")) {
    const bool success = starts_with(name, "task_success_rate") ||
                         starts_with(name, "decision_match_rate") ||
                         ends_with(name, "context_found_rate");
    return rate_metric(success ? Better::higher : Better::neither);
  }
  for (const char* word : {"error", "mse", "distance", "time", "seconds", "duration"}) {
    if (!words.count(word)) continue;
    const std::string last = list.back();
    // Old names end in their unit, a word of one or two letters (mm, m, s).
    const bool unit = last.size() <= 2 && std::all_of(last.begin(), last.end(), [](char c) {
                        return std::isalpha(static_cast<unsigned char>(c));
                      });
    return error_metric(unit ? last : "");
  }
  if (words.count("failures")) return count_metric(Better::lower);
  for (const char* word : {"expected", "demonstrations", "parameters"}) {
    if (words.count(word)) return count_metric(Better::neither);
  }
  return declaration;
}

}  // namespace corrmp
