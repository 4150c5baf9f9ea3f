// A synthetic family of one-dimensional curves parameterised by a context value
// c, for trying CNMPs without simulation and for the learning tests:
//   y(t) = (0.5 + 0.5 c) sin(pi (1 + c) t) + 0.3 c t,  t in [0, 1].
// Each demonstration is one segment ("full") with x = t, y = y(t), context = c.
#pragma once

#include "core/config/field_rule.hpp"
#include "envs/demonstration_source.hpp"

namespace corrmp {

struct CurveFamilyParams {
  int train = 30;
  int validation = 10;
  int time_steps = 50;
  double context_min = 0.0;
  double context_max = 1.0;
  double noise = 0.0;

  template <class Fields>
  void describe(Fields& f) {
    f("train", train, "number of training curves", in_range(1, 1000000));
    f("validation", validation, "number of validation curves", in_range(0, 1000000));
    f("time_steps", time_steps, "points per curve", in_range(2, 100000));
    f("context_min", context_min, "smallest context value drawn", in_range(-1000.0, 1000.0));
    f("context_max", context_max, "largest context value drawn", in_range(-1000.0, 1000.0));
    f("noise", noise,
      "standard deviation of Gaussian noise added to y (whose values lie in about [-1, 1.3])",
      in_range(0.0, 1000.0));
  }
};

double curve_family_value(double context, double t);

class CurveFamily : public DemonstrationSource {
 public:
  explicit CurveFamily(const CurveFamilyParams& params);
  DemonstrationSplit collect(Environment* environment, Rng& rng) override;
  std::vector<std::string> segments() const override { return {"full"}; }
  bool provides_contexts() const override { return true; }
  Demonstration make(double context, Rng& rng) const;
  std::vector<MemoryNeed> memory_needs(const Environment* environment) const override;
  int64_t longest_trajectory(const Environment*) const override { return params_.time_steps; }

 private:
  CurveFamilyParams params_;
};

}  // namespace corrmp
