// Perfect-state contexts.
#include "context/perfect_context.hpp"

namespace corrmp {

std::vector<std::string> PerfectContext::segments() const {
  std::vector<std::string> names;
  for (const auto& spec : params_.segments) names.push_back(spec.segment);
  return names;
}

std::vector<std::string> PerfectContext::state_names() const {
  std::vector<std::string> names;
  for (const auto& spec : params_.segments)
    names.insert(names.end(), spec.state.begin(), spec.state.end());
  return names;
}

Eigen::VectorXd PerfectContext::extract(const std::string& segment,
                                        const Observation& observation) {
  for (const auto& spec : params_.segments) {
    if (spec.segment != segment) continue;
    Eigen::VectorXd context(static_cast<Eigen::Index>(spec.state.size()));
    for (size_t i = 0; i < spec.state.size(); ++i) context[i] = observation.value(spec.state[i]);
    return context;
  }
  return Eigen::VectorXd();
}

}  // namespace corrmp
