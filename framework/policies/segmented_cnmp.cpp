// One CNMP per segment.
#include "policies/segmented_cnmp.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <filesystem>
#include <set>

#include "cnmp/cnmp_memory.hpp"
#include "core/parameter_error.hpp"
#include "core/thread_budget.hpp"

namespace corrmp {

std::vector<CnmpTrajectory> segment_trajectories(const std::vector<Demonstration>& demos,
                                                 const std::string& segment, bool use_context) {
  std::vector<CnmpTrajectory> out;
  for (size_t i = 0; i < demos.size(); ++i) {
    const SegmentTrajectory* s = demos[i].find(segment);
    if (s == nullptr) {
      throw std::runtime_error(fmt::format("demonstration {} has no segment '{}'", i, segment));
    }
    out.push_back({s->x, s->y, use_context ? s->context : Eigen::VectorXd()});
  }
  return out;
}

SegmentedCnmp::SegmentedCnmp(const SegmentedCnmpParams& params, uint64_t seed)
    : params_(params), seed_(seed) {
  if (params_.segments.empty()) {
    throw ParameterError("segments", "lists no segment: a segmented policy needs at least one");
  }
  std::set<std::string> seen;
  for (size_t i = 0; i < params_.segments.size(); ++i) {
    const std::string key = fmt::format("segments[{}].name", i);
    check_file_name(key, params_.segments[i].name);
    if (!seen.insert(params_.segments[i].name).second) {
      throw ParameterError(key, fmt::format("segment '{}' is listed twice: each segment has one "
                                            "CNMP",
                                            params_.segments[i].name));
    }
  }
}

// The segment networks are independent, so they train concurrently (core/thread_budget.hpp).
// Each trains on its own stream, derived from one draw of `rng` and the segment's name, so the
// models are the same whatever the number of threads, and whichever networks a call trains.
std::vector<PolicyTrainingSummary> SegmentedCnmp::fit(const std::vector<Demonstration>& train,
                                                      const std::vector<Demonstration>& validation,
                                                      Rng rng, Networks which) {
  const uint64_t training_seed = rng();
  std::vector<const SegmentSpec*> wanted;
  for (const auto& segment : params_.segments) {
    if (which == Networks::all || (which == Networks::with_context) == segment.use_context)
      wanted.push_back(&segment);
  }
  const size_t count = wanted.size();
  std::vector<PolicyTrainingSummary> summaries(count);
  std::vector<std::unique_ptr<CnmpModel>> models(count);
  parallel_for(static_cast<int>(count), [&](int index) {
    const SegmentSpec& segment = *wanted[static_cast<size_t>(index)];
    const auto train_data = segment_trajectories(train, segment.name, segment.use_context);
    const auto validation_data =
        segment_trajectories(validation, segment.name, segment.use_context);
    CnmpArchitecture architecture = params_.network;
    architecture.d_x = static_cast<int>(train_data.front().x.cols());
    architecture.d_y = static_cast<int>(train_data.front().y.cols());
    architecture.d_context = static_cast<int>(train_data.front().context.size());
    auto model = std::make_unique<CnmpModel>(architecture, mix64(seed_ ^ fnv1a64(segment.name)));
    spdlog::info("training the '{}' CNMP: {} parameters, d_x {}, d_y {}, context {}", segment.name,
                 model->network().parameter_count(), architecture.d_x, architecture.d_y,
                 architecture.d_context);
    Rng segment_rng(mix64(training_seed ^ fnv1a64(segment.name)));
    PolicyTrainingSummary& summary = summaries[static_cast<size_t>(index)];
    summary = {segment.name, {}, model->network().parameter_count()};
    summary.report = train_cnmp(*model, train_data, validation_data, params_.training, segment_rng,
                                "train " + segment.name);
    models[static_cast<size_t>(index)] = std::move(model);
  });
  const std::lock_guard<std::mutex> lock(models_mutex_);
  for (size_t i = 0; i < count; ++i) models_[wanted[i]->name] = std::move(models[i]);
  return summaries;
}

std::vector<MemoryNeed> SegmentedCnmp::memory_needs(int64_t longest) const {
  std::vector<MemoryNeed> needs = cnmp_training_needs(params_.network, params_.training, longest);
  const size_t segments = params_.segments.size();
  for (auto& need : needs) {
    need.bytes *= static_cast<double>(segments);
    if (segments > 1) need.what += fmt::format(", for each of the {} CNMPs", segments);
  }
  return needs;
}

std::vector<std::string> SegmentedCnmp::segments() const {
  std::vector<std::string> names;
  for (const auto& s : params_.segments) names.push_back(s.name);
  return names;
}

std::vector<std::string> SegmentedCnmp::context_segments() const {
  std::vector<std::string> names;
  for (const auto& s : params_.segments) {
    if (s.use_context) names.push_back(s.name);
  }
  return names;
}

CnmpPrediction SegmentedCnmp::generate(const std::string& segment,
                                       const Eigen::MatrixXd& observations,
                                       const Eigen::VectorXd& context,
                                       const Eigen::MatrixXd& query_x) {
  const auto it = models_.find(segment);
  if (it == models_.end()) {
    throw std::runtime_error(fmt::format("no trained CNMP for segment '{}'", segment));
  }
  const bool use_context = it->second->architecture().d_context > 0;
  return it->second->predict(observations, use_context ? context : Eigen::VectorXd(), query_x);
}

void SegmentedCnmp::save(const std::string& directory) {
  std::filesystem::create_directories(directory);
  for (const auto& [name, model] : models_) model->save(directory + "/" + name + ".cnmp");
}

}  // namespace corrmp
