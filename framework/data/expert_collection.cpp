// Filling an expert's demonstration split (expert_collection.hpp).
#include "data/expert_collection.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "core/interrupt.hpp"
#include "core/progress.hpp"

namespace corrmp {

DemonstrationSplit collect_expert_demonstrations(const ExpertCollection& wanted,
                                                 const std::function<Demonstration()>& attempt) {
  const int total = wanted.train + wanted.validation;
  DemonstrationSplit split;
  Progress progress("demonstrations", total);
  const auto collected = [&] {
    return static_cast<int>(split.train.size() + split.validation.size());
  };
  int tried = 0, dropped = 0;
  for (; tried < wanted.max_attempts && collected() < total; ++tried) {
    check_interrupt();
    try {
      Demonstration demo = attempt();
      auto& into =
          static_cast<int>(split.train.size()) < wanted.train ? split.train : split.validation;
      into.push_back(std::move(demo));
      progress.advance();
    } catch (const std::runtime_error& e) {
      ++dropped;
      spdlog::debug("{}: demonstration dropped: {}", wanted.expert, e.what());
    }
  }
  progress.finish(fmt::format("{} dropped", dropped));
  if (collected() < total) {
    throw std::runtime_error(
        fmt::format("{} succeeded on only {} of the {} scenarios tried ({} wanted)", wanted.expert,
                    collected(), tried, total));
  }
  if (dropped > 0) spdlog::info("{}: {} demonstrations dropped", wanted.expert, dropped);
  return split;
}

}  // namespace corrmp
