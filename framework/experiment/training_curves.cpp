// Writing the training curves (training_curves.hpp).
#include "experiment/training_curves.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace corrmp {

namespace {

std::string number(double value) {
  return std::isfinite(value) ? fmt::format("{:.6g}", value) : "";
}

}  // namespace

void write_training_curves(const std::vector<PolicyTrainingSummary>& summaries,
                           const std::string& path) {
  std::ofstream out(path);
  out << "network,update,loss,validation_error_mean,validation_error_max\n";
  for (const auto& summary : summaries) {
    for (const auto& point : summary.report.curve) {
      out << summary.segment << ',' << point.update << ',' << number(point.loss) << ','
          << number(point.validation_mean) << ',' << number(point.validation_max) << '\n';
    }
  }
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace corrmp
