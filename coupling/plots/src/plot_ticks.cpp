#include "plot_ticks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rockfdem::plots {
namespace {

// The round step nearest to `raw`: 1, 2 or 5 times a power of ten.
double round_step(double raw) {
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / p;
  return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * p;
}

}  // namespace

std::string Ticks::label(double v) const {
  char s[32];
  if (std::abs(v) < 0.5 * step) return "0";  // not "-0.00"
  std::snprintf(s, sizeof s, "%.*f", decimals, v);
  return s;
}

Ticks ticks_at(double lo, double hi, double step) {
  Ticks t;
  if (!(hi > lo) || !(step > 0) || !std::isfinite(lo) || !std::isfinite(hi)) return t;
  t.step = step;
  const double eps = 1e-9 * (hi - lo);
  for (double k = std::ceil((lo - eps) / step); k * step <= hi + eps; ++k)
    t.values.push_back(k * step);
  t.decimals = std::max(0, int(-std::floor(std::log10(step) + 1e-9)));
  return t;
}

Ticks nice_ticks(double lo, double hi, int target) {
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return {};
  const Ticks t = ticks_at(lo, hi, round_step((hi - lo) / std::max(1, target - 1)));
  // A range just short of two multiples: halve the step (bounded: 2^10 finer at most).
  if (t.values.size() < 2 && target < 1000) return nice_ticks(lo, hi, 2 * target);
  return t;
}

double round_length(double length) {
  if (!(length > 0)) return 0;
  const double p = std::pow(10.0, std::floor(std::log10(length)));
  const double f = length / p;
  return (f >= 5 ? 5 : f >= 2 ? 2 : 1) * p;
}

}  // namespace rockfdem::plots
