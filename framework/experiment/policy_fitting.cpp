// The training stage (policy_fitting.hpp).
#include "experiment/policy_fitting.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <future>
#include <system_error>

#include "core/interrupt.hpp"
#include "core/thread_budget.hpp"

namespace corrmp {

namespace {

// Sets `flag` when the scope is left by an exception.
class SetOnError {
 public:
  explicit SetOnError(std::atomic<bool>& flag)
      : flag_(flag), exceptions_(std::uncaught_exceptions()) {}
  ~SetOnError() {
    if (std::uncaught_exceptions() > exceptions_) flag_ = true;
  }
  SetOnError(const SetOnError&) = delete;
  SetOnError& operator=(const SetOnError&) = delete;

 private:
  std::atomic<bool>& flag_;
  int exceptions_;
};

// Whether some network of `policy` reads no context (and could train before the contexts exist).
bool has_context_free_network(const Policy& policy) {
  const std::vector<std::string> with_context = policy.context_segments();
  for (const auto& segment : policy.segments()) {
    if (std::find(with_context.begin(), with_context.end(), segment) == with_context.end())
      return true;
  }
  return false;
}

void sort_by_segment(const Policy& policy, std::vector<PolicyTrainingSummary>& summaries) {
  const std::vector<std::string> order = policy.segments();
  const auto rank = [&](const PolicyTrainingSummary& s) {
    return std::find(order.begin(), order.end(), s.segment) - order.begin();
  };
  std::stable_sort(summaries.begin(), summaries.end(),
                   [&](const auto& a, const auto& b) { return rank(a) < rank(b); });
}

}  // namespace

std::vector<PolicyTrainingSummary> fit_extractor_and_policy(Policy& policy,
                                                            ContextExtractor* extractor,
                                                            DemonstrationSplit& demos,
                                                            const PolicyFitting& fitting) {
  const Rng& rng = fitting.policy_rng;
  if (!extractor) return policy.fit(demos.train, demos.validation, rng);

  // Declared before the thread, so they outlive it even when an error unwinds.
  std::atomic<bool> abandoned{false};
  const bool beside = thread_budget() >= 2 && has_context_free_network(policy);
  const DemonstrationSplit copy = beside ? demos : DemonstrationSplit{};
  std::future<std::vector<PolicyTrainingSummary>> context_free;
  if (beside) {
    try {
      context_free = std::async(std::launch::async, [&policy, &copy, &abandoned, rng] {
        const InlineLoops one_thread;
        const StopWhen stop(abandoned);
        return policy.fit(copy.train, copy.validation, rng, Networks::without_context);
      });
    } catch (const std::system_error& e) {
      spdlog::debug("no thread for the networks without context ({}): they train after", e.what());
    }
  }
  // Destroyed first: an error from here on stops that thread instead of waiting for its training.
  const SetOnError abandon_on_error(abandoned);

  Rng extractor_rng = fitting.extractor_rng;
  std::vector<Demonstration> all = demos.train;
  all.insert(all.end(), demos.validation.begin(), demos.validation.end());
  extractor->fit(all, fitting.cache, extractor_rng);
  assign_contexts(*extractor, demos.train);
  assign_contexts(*extractor, demos.validation);
  extractor->write_outputs(fitting.output_dir, demos.validation);

  std::vector<PolicyTrainingSummary> summaries =
      policy.fit(demos.train, demos.validation, rng, Networks::with_context);
  std::vector<PolicyTrainingSummary> without_context;
  if (context_free.valid()) {
    const SpareThread waiting;  // its core may speed up the networks still training
    without_context = context_free.get();
  } else {
    without_context = policy.fit(demos.train, demos.validation, rng, Networks::without_context);
  }
  for (auto& summary : without_context) summaries.push_back(std::move(summary));
  sort_by_segment(policy, summaries);
  return summaries;
}

}  // namespace corrmp
