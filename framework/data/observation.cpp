// Observations and scenarios.
#include "data/observation.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "core/json_writer.hpp"

namespace corrmp {

double Observation::value(const std::string& name) const {
  const auto it = state.find(name);
  if (it == state.end()) {
    std::string known;
    for (const auto& [key, v] : state) known += (known.empty() ? "" : ", ") + key;
    throw std::runtime_error(
        fmt::format("the observation has no state value '{}' (it has: {})", name, known));
  }
  return it->second;
}

std::string scenario_json(const Scenario& scenario) {
  JsonObject json;
  for (const auto& [key, value] : scenario) json.add(key, value);
  return json.str();
}

}  // namespace corrmp
