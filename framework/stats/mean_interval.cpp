// Means across seeds with Student t and Welch intervals (mean_interval.hpp).
#include "stats/mean_interval.hpp"

#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "stats/distributions.hpp"

namespace corrmp {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void check_confidence(double confidence) {
  if (!(confidence > 0.0 && confidence < 1.0)) {
    throw std::invalid_argument("confidence must lie in (0, 1)");
  }
}

double sample_mean(const std::vector<double>& samples) {
  if (samples.empty()) return kNaN;
  return std::accumulate(samples.begin(), samples.end(), 0.0) / samples.size();
}

// Unbiased sample variance; NaN below two samples.
double sample_variance(const std::vector<double>& samples) {
  if (samples.size() < 2) return kNaN;
  const double mean = sample_mean(samples);
  double sum = 0.0;
  for (double x : samples) sum += (x - mean) * (x - mean);
  return sum / (samples.size() - 1);
}

}  // namespace

bool MeanInterval::defined() const { return !std::isnan(half_width); }
bool DifferenceInterval::defined() const { return !std::isnan(half_width); }

MeanInterval mean_interval(const std::vector<double>& samples, double confidence) {
  check_confidence(confidence);
  MeanInterval m;
  m.count = static_cast<int>(samples.size());
  m.mean = sample_mean(samples);
  m.stddev = std::sqrt(sample_variance(samples));
  m.half_width = samples.size() < 2 ? kNaN
                                    : student_t_quantile(0.5 + confidence / 2, m.count - 1.0) *
                                          m.stddev / std::sqrt(static_cast<double>(m.count));
  m.low = m.mean - m.half_width;
  m.high = m.mean + m.half_width;
  return m;
}

DifferenceInterval difference_interval(const std::vector<double>& a, const std::vector<double>& b,
                                       double confidence) {
  check_confidence(confidence);
  DifferenceInterval d;
  d.difference = sample_mean(b) - sample_mean(a);
  const double va = sample_variance(a) / a.size(), vb = sample_variance(b) / b.size();
  const double se2 = va + vb;  // NaN when either has fewer than two samples
  if (std::isnan(se2)) {
    d.dof = d.half_width = kNaN;
  } else if (se2 == 0.0) {
    d.dof = static_cast<double>(a.size() + b.size() - 2);
    d.half_width = 0.0;
  } else {
    d.dof = se2 * se2 / (va * va / (a.size() - 1) + vb * vb / (b.size() - 1));
    d.half_width = student_t_quantile(0.5 + confidence / 2, d.dof) * std::sqrt(se2);
  }
  d.low = d.difference - d.half_width;
  d.high = d.difference + d.half_width;
  return d;
}

}  // namespace corrmp
