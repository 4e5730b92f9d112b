#include "study/ensemble_stats.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

namespace rockfdem::workflows::study {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr long kLongestSum = 200;  // df beyond: the expansion, its error below 2e-12

// The x in [lo, hi] where the increasing f reaches `target`, to the
// spacing of doubles (100 halvings of a range of at most 40).
double bisect(const std::function<double(double)>& f, double target, double lo, double hi) {
  for (int i = 0; i < 100; ++i) {
    const double mid = (lo + hi) / 2;
    (f(mid) < target ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

// P(|T| <= sqrt(df) tan(theta)) for Student's t: the finite sums of
// Abramowitz & Stegun 26.7.3 (odd df) and 26.7.4 (even df), all terms
// positive, so exact to round-off.
double central_probability(double theta, long df) {
  const double c2 = std::cos(theta) * std::cos(theta), s = std::sin(theta);
  if (df == 1) return 2 * theta / kPi;
  const bool even = df % 2 == 0;
  double term = 1, sum = 1;
  for (long k = 1; 2 * k + (even ? 0 : 1) <= df - 2; ++k) {
    term *= even ? c2 * double(2 * k - 1) / double(2 * k) : c2 * double(2 * k) / double(2 * k + 1);
    sum += term;
  }
  return even ? s * sum : 2 / kPi * (theta + s * std::cos(theta) * sum);
}

// Cornish-Fisher for t (Abramowitz & Stegun 26.7.5): x the normal quantile.
double fisher_expansion(double x, double df) {
  const double x2 = x * x;
  const double g1 = x * (x2 + 1) / 4;
  const double g2 = x * ((5 * x2 + 16) * x2 + 3) / 96;
  const double g3 = x * (((3 * x2 + 19) * x2 + 17) * x2 - 15) / 384;
  const double g4 = x * ((((79 * x2 + 776) * x2 + 1482) * x2 - 1920) * x2 - 945) / 92160;
  return x + (g1 + (g2 + (g3 + g4 / df) / df) / df) / df;
}

}  // namespace

double student_t_quantile(double p, long df) {
  if (!(p > 0 && p < 1) || df < 1) throw std::invalid_argument("student_t_quantile: p or df");
  if (p < 0.5) return -student_t_quantile(1 - p, df);
  if (df > kLongestSum) {
    const double z =
        bisect([](double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }, p, 0, 40);
    return fisher_expansion(z, double(df));
  }
  const double theta =
      bisect([df](double t) { return central_probability(t, df); }, 2 * p - 1, 0, kPi / 2);
  return std::sqrt(double(df)) * std::tan(theta);
}

SampleStats describe_sample(const std::vector<double>& values) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  SampleStats s{values.size(), kNaN, kNaN, kNaN, kNaN, kNaN, kNaN};
  if (values.empty()) return s;
  double sum = 0;
  for (double v : values) sum += v;
  s.mean = sum / double(s.n);
  s.min = *std::min_element(values.begin(), values.end());
  s.max = *std::max_element(values.begin(), values.end());
  if (s.n < 2) return s;
  double squares = 0;  // about the mean: no cancellation of large sums
  for (double v : values) squares += (v - s.mean) * (v - s.mean);
  s.std = std::sqrt(squares / double(s.n - 1));
  const double half = student_t_quantile(0.975, long(s.n) - 1) * s.std / std::sqrt(double(s.n));
  s.ci95_low = s.mean - half;
  s.ci95_high = s.mean + half;
  return s;
}

}  // namespace rockfdem::workflows::study
