// Filling an expert's demonstration split in parallel (expert_collection.hpp).
#include "data/expert_collection.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <atomic>
#include <exception>
#include <iterator>
#include <limits>
#include <mutex>
#include <optional>
#include <set>
#include <vector>

#include "core/interrupt.hpp"
#include "core/progress.hpp"
#include "core/thread_budget.hpp"

namespace corrmp {

namespace {

// What became of one attempt.
struct AttemptResult {
  std::optional<Demonstration> demonstration;  // when it succeeded
  std::exception_ptr fatal;                    // an error that stops the collection
  bool ran = false;
};

}  // namespace

Rng expert_attempt_stream(uint64_t base, int index) {
  return Rng(mix64(base ^ mix64(static_cast<uint64_t>(index))));
}

DemonstrationSplit collect_expert_demonstrations(const ExpertCollection& wanted, Rng& rng,
                                                 int workers, const ExpertAttempt& attempt) {
  const int total = wanted.train + wanted.validation;
  const uint64_t base = rng();
  if (total <= 0) return {};
  std::vector<AttemptResult> results(static_cast<size_t>(std::max(wanted.max_attempts, 0)));
  Progress progress("demonstrations", total);
  // An attempt is superfluous once `total` attempts of lower index have succeeded, or one of
  // lower index failed fatally: a single thread would never have made it. `cutoff` is the
  // index of the total-th success so far (it only decreases), `first_fatal` the lowest fatal
  // failure.
  std::mutex successes_mutex;
  std::set<int> successes;
  std::atomic<int> cutoff{std::numeric_limits<int>::max()};
  std::atomic<int> first_fatal{std::numeric_limits<int>::max()};
  parallel_for_with_workers(wanted.max_attempts, workers, [&](int index, int worker) {
    if (index > cutoff.load() || index > first_fatal.load()) return;
    AttemptResult& result = results[static_cast<size_t>(index)];
    result.ran = true;
    Rng attempt_rng = expert_attempt_stream(base, index);
    try {
      result.demonstration = attempt(attempt_rng, worker);
      {
        std::lock_guard<std::mutex> lock(successes_mutex);
        successes.insert(index);
        if (static_cast<int>(successes.size()) >= total) {
          cutoff = *std::next(successes.begin(), total - 1);
        }
      }
      progress.advance();
    } catch (const Interrupted&) {
      throw;
    } catch (const std::runtime_error& e) {
      spdlog::debug("{}: demonstration {} dropped: {}", wanted.expert, index, e.what());
    } catch (...) {
      result.fatal = std::current_exception();
      int lowest = first_fatal.load();
      while (index < lowest && !first_fatal.compare_exchange_weak(lowest, index)) {
      }
    }
  });

  // The attempts a single thread would have made: up to the total-th success, or all.
  DemonstrationSplit split;
  int tried = 0, dropped = 0;
  for (AttemptResult& result : results) {
    if (static_cast<int>(split.train.size() + split.validation.size()) >= total) break;
    if (!result.ran) break;  // never before a fatal error (rethrown) or the total-th success
    ++tried;
    if (result.fatal) std::rethrow_exception(result.fatal);
    if (!result.demonstration) {
      ++dropped;
      continue;
    }
    auto& into =
        static_cast<int>(split.train.size()) < wanted.train ? split.train : split.validation;
    into.push_back(std::move(*result.demonstration));
  }
  const int collected = static_cast<int>(split.train.size() + split.validation.size());
  progress.finish(fmt::format("{} dropped", dropped));
  if (collected < total) {
    throw std::runtime_error(
        fmt::format("{} succeeded on only {} of the {} scenarios tried ({} wanted)", wanted.expert,
                    collected, tried, total));
  }
  if (dropped > 0) spdlog::info("{}: {} demonstrations dropped", wanted.expert, dropped);
  return split;
}

}  // namespace corrmp
