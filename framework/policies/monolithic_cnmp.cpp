// The monolithic CNMP baseline with a matched parameter budget.
#include "policies/monolithic_cnmp.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <filesystem>

#include "cnmp/cnmp_memory.hpp"
#include "core/parameter_error.hpp"
#include "policies/segmented_cnmp.hpp"

namespace corrmp {

MonolithicCnmp::MonolithicCnmp(const MonolithicCnmpParams& params, uint64_t seed)
    : params_(params), seed_(seed) {
  check_file_name("segment", params_.segment);
}

std::vector<MemoryNeed> MonolithicCnmp::memory_needs(int64_t longest) const {
  return cnmp_training_needs(params_.network, params_.training, longest);
}

std::vector<PolicyTrainingSummary> MonolithicCnmp::fit(const std::vector<Demonstration>& train,
                                                       const std::vector<Demonstration>& validation,
                                                       Rng rng, Networks which) {
  // The one network reads the skill's context.
  if (which == Networks::without_context) return {};
  const auto train_data = segment_trajectories(train, params_.segment, true);
  const auto validation_data = segment_trajectories(validation, params_.segment, true);
  CnmpArchitecture architecture = params_.network;
  architecture.d_x = static_cast<int>(train_data.front().x.cols());
  architecture.d_y = static_cast<int>(train_data.front().y.cols());
  architecture.d_context = static_cast<int>(train_data.front().context.size());

  if (!params_.matched_segments.empty()) {
    int64_t budget = 0;
    for (const auto& name : params_.matched_segments) {
      const bool no_context =
          std::find(params_.matched_without_context.begin(), params_.matched_without_context.end(),
                    name) != params_.matched_without_context.end();
      const SegmentTrajectory& s = *train.front().find(name);
      CnmpArchitecture part = params_.network;
      part.d_x = static_cast<int>(s.x.cols());
      part.d_y = static_cast<int>(s.y.cols());
      part.d_context = no_context ? 0 : static_cast<int>(s.context.size());
      budget += cnmp_parameter_count(part);
    }
    architecture.width = width_for_parameter_budget(architecture, budget);
    spdlog::info("monolithic CNMP: width {} gives {} parameters for a budget of {} ({})",
                 architecture.width, cnmp_parameter_count(architecture), budget,
                 fmt::join(params_.matched_segments, " + "));
  }
  model_ = std::make_unique<CnmpModel>(architecture, mix64(seed_ ^ fnv1a64(params_.segment)));
  PolicyTrainingSummary summary{params_.segment, {}, model_->network().parameter_count()};
  summary.report = train_cnmp(*model_, train_data, validation_data, params_.training, rng,
                              "train " + params_.segment);
  return {summary};
}

std::vector<std::string> MonolithicCnmp::data_segments() const {
  std::vector<std::string> names{params_.segment};
  names.insert(names.end(), params_.matched_segments.begin(), params_.matched_segments.end());
  return names;
}

CnmpPrediction MonolithicCnmp::generate(const std::string& segment,
                                        const Eigen::MatrixXd& observations,
                                        const Eigen::VectorXd& context,
                                        const Eigen::MatrixXd& query_x) {
  if (!model_ || segment != params_.segment) {
    throw std::runtime_error(fmt::format("no trained CNMP for segment '{}'", segment));
  }
  return model_->predict(observations, context, query_x);
}

void MonolithicCnmp::save(const std::string& directory) {
  std::filesystem::create_directories(directory);
  if (model_) model_->save(directory + "/" + params_.segment + ".cnmp");
}

}  // namespace corrmp
