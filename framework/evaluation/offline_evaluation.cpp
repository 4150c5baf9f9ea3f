// Offline evaluation of segment predictions against held-out demonstrations.
#include "evaluation/offline_evaluation.hpp"

#include <fmt/format.h>
#include <fmt/os.h>

#include <filesystem>

#include "cnmp/cnmp_trainer.hpp"

namespace corrmp {

namespace {

std::string csv_header(const SegmentTrajectory& s) {
  std::string header = "demonstration,step";
  for (Eigen::Index i = 0; i < s.x.cols(); ++i) header += fmt::format(",x{}", i);
  for (const char* kind : {"y", "mean", "std"}) {
    for (Eigen::Index i = 0; i < s.y.cols(); ++i) header += fmt::format(",{}{}", kind, i);
  }
  return header;
}

}  // namespace

std::vector<SegmentErrors> evaluate_offline(Policy& policy,
                                            const std::vector<Demonstration>& demonstrations,
                                            const std::string& csv_directory) {
  std::vector<SegmentErrors> results;
  if (demonstrations.empty()) return results;
  if (!csv_directory.empty()) std::filesystem::create_directories(csv_directory);
  for (const std::string& segment : policy.segments()) {
    TrajectoryErrorAccumulator errors;
    std::string csv;
    for (size_t d = 0; d < demonstrations.size(); ++d) {
      const SegmentTrajectory* s = demonstrations[d].find(segment);
      if (s == nullptr) {
        throw std::runtime_error(fmt::format("demonstration {} has no segment '{}'", d, segment));
      }
      const CnmpPrediction p =
          policy.generate(segment, first_observation(s->x, s->y), s->context, s->x);
      errors.add(mean_row_distance(p.mean, s->y));
      if (csv_directory.empty()) continue;
      if (csv.empty()) csv = csv_header(*s) + "\n";
      for (Eigen::Index t = 0; t < s->x.rows(); ++t) {
        csv += fmt::format("{},{}", d, t);
        for (const Eigen::MatrixXd* m : {&s->x, &s->y, &p.mean, &p.std}) {
          for (Eigen::Index i = 0; i < m->cols(); ++i) csv += fmt::format(",{}", (*m)(t, i));
        }
        csv += "\n";
      }
    }
    if (!csv_directory.empty()) {
      auto out = fmt::output_file(csv_directory + "/" + segment + ".csv");
      out.print("{}", csv);
    }
    results.push_back({segment, errors.result()});
  }
  return results;
}

}  // namespace corrmp
