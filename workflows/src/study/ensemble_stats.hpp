// Statistics of an ensemble: the same figure from several realisations of
// the rock's strength heterogeneity (one run per heterogeneity_seed).
#pragma once

#include <cstddef>
#include <vector>

namespace rockfdem::workflows::study {

/// A sample's summary. Undefined entries are NaN: all but n for an empty
/// sample; std and the interval for a single value.
struct SampleStats {
  std::size_t n = 0;
  double mean, std;            ///< std: the sample standard deviation (divisor n - 1)
  double ci95_low, ci95_high;  ///< mean -+ t_{0.975, n-1} std / sqrt(n) (Student t)
  double min, max;
};

SampleStats describe_sample(const std::vector<double>& values);

/// The p-quantile of Student's t with df >= 1 degrees of freedom, p in (0, 1).
/// To 1e-13 relative for df <= 200 (the exact finite sums of its
/// distribution, inverted by bisection) and to 2e-12 beyond (Fisher's
/// expansion in 1/df to the fourth order about the normal quantile).
double student_t_quantile(double p, long df);

}  // namespace rockfdem::workflows::study
