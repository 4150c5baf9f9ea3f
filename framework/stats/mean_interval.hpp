// The mean of a metric across runs (seeds) with its confidence interval from
// Student's t with n - 1 degrees of freedom, and the difference of two such
// means with Welch's interval: what the comparison and reproduction reports
// print for every metric across seeds.
#pragma once

#include <vector>

namespace corrmp {

struct MeanInterval {
  int count = 0;        // the samples (runs)
  double mean = 0.0;    // NaN without samples
  double stddev = 0.0;  // sample standard deviation (n - 1); NaN below 2 samples
  // The interval mean -/+ half_width. Undefined, so NaN, below 2 samples: one
  // run says nothing about the spread across seeds.
  double half_width = 0.0;
  double low = 0.0, high = 0.0;
  bool defined() const;  // whether the interval is (2 or more samples)
};

// `confidence` in (0, 1), e.g. 0.95.
MeanInterval mean_interval(const std::vector<double>& samples, double confidence = 0.95);

struct DifferenceInterval {
  double difference = 0.0;  // mean(b) - mean(a); NaN if either has no sample
  double dof = 0.0;         // Welch-Satterthwaite degrees of freedom
  double half_width = 0.0;  // NaN unless both have 2 or more samples
  double low = 0.0, high = 0.0;
  bool defined() const;
};

// mean(b) - mean(a) with Welch's interval (unequal variances). When both
// samples have no spread the interval is the point itself.
DifferenceInterval difference_interval(const std::vector<double>& a, const std::vector<double>& b,
                                       double confidence = 0.95);

}  // namespace corrmp
