// Synthetic context-parameterised curves.
#include "cnmp/curve_family.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/json_writer.hpp"
#include "core/parameter_error.hpp"

namespace corrmp {

double curve_family_value(double context, double t) {
  return (0.5 + 0.5 * context) * std::sin(M_PI * (1.0 + context) * t) + 0.3 * context * t;
}

CurveFamily::CurveFamily(const CurveFamilyParams& params) : params_(params) {
  if (params_.context_min > params_.context_max) {
    throw ParameterError("context_max",
                         "is below context_min: the contexts are drawn from "
                         "[context_min, context_max]");
  }
}

Demonstration CurveFamily::make(double context, Rng& rng) const {
  const int steps = params_.time_steps;
  SegmentTrajectory segment{"full", Eigen::MatrixXd(steps, 1), Eigen::MatrixXd(steps, 1),
                            Eigen::VectorXd::Constant(1, context), Observation{}};
  for (int i = 0; i < steps; ++i) {
    const double t = static_cast<double>(i) / (steps - 1);
    segment.x(i, 0) = t;
    segment.y(i, 0) = curve_family_value(context, t) +
                      (params_.noise > 0.0 ? rng.normal(0.0, params_.noise) : 0.0);
  }
  return Demonstration{JsonObject().add("context", context).str(), {segment}, ""};
}

std::vector<MemoryNeed> CurveFamily::memory_needs(const Environment*) const {
  const double curves = static_cast<double>(params_.train) + params_.validation;
  // x, y and the normalised copies training makes, in doubles and floats.
  const double bytes = curves * params_.time_steps * 2.0 * (2 * sizeof(double) + sizeof(float));
  return {{bytes, "train",
           fmt::format("{} curves of {} points", params_.train + params_.validation,
                       params_.time_steps)}};
}

DemonstrationSplit CurveFamily::collect(Environment*, Rng& rng) {
  DemonstrationSplit split;
  for (int i = 0; i < params_.train + params_.validation; ++i) {
    const double context = rng.uniform(params_.context_min, params_.context_max);
    (i < params_.train ? split.train : split.validation).push_back(make(context, rng));
  }
  return split;
}

}  // namespace corrmp
