// The robot's base moved per scenario (base_offset.hpp).
#include "sim/robot/base_offset.hpp"

#include <algorithm>

namespace corrmp {

namespace {

constexpr const char* kKeys[3] = {"base_dx", "base_dy", "base_dz"};

}  // namespace

bool moves_base(const std::vector<double>& range) {
  return std::any_of(range.begin(), range.end(), [](double r) { return r != 0.0; });
}

void draw_base_offset(const std::vector<double>& range, Rng& rng, Scenario& scenario) {
  if (!moves_base(range)) return;
  for (size_t i = 0; i < 3; ++i) scenario[kKeys[i]] = rng.uniform(-range.at(i), range.at(i));
}

DualArmParams with_base_offset(DualArmParams params, const Scenario& scenario) {
  for (size_t i = 0; i < 3; ++i) {
    const auto it = scenario.find(kKeys[i]);
    if (it != scenario.end()) params.base_position.at(i) += it->second;
  }
  return params;
}

}  // namespace corrmp
