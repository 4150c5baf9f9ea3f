// One CNMP per segment.
#include "policies/segmented_cnmp.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <filesystem>

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
    : params_(params), seed_(seed) {}

std::vector<PolicyTrainingSummary> SegmentedCnmp::fit(const std::vector<Demonstration>& train,
                                                      const std::vector<Demonstration>& validation,
                                                      Rng& rng) {
  std::vector<PolicyTrainingSummary> summaries;
  models_.clear();
  for (const SegmentSpec& segment : params_.segments) {
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
    PolicyTrainingSummary summary{segment.name, {}, model->network().parameter_count()};
    summary.report = train_cnmp(*model, train_data, validation_data, params_.training, rng,
                                "train " + segment.name);
    summaries.push_back(summary);
    models_[segment.name] = std::move(model);
  }
  return summaries;
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
