// Tick values an engineer reads at a glance: multiples of 1, 2 or 5 times a
// power of ten, written with as many decimals as the step needs ("-20",
// "2.5", "0.05"; never "166." or "8.48").
#pragma once

#include <string>
#include <vector>

namespace rockfdem::plots {

struct Ticks {
  double step = 0;
  std::vector<double> values;  ///< the multiples of step in [lo, hi], ascending
  int decimals = 0;            ///< what the step needs
  std::string label(double v) const;
};

/// About `target` (at least 2 where the range allows) round ticks in [lo, hi].
Ticks nice_ticks(double lo, double hi, int target = 6);

/// The multiples of `step` in [lo, hi], written as `step` needs.
Ticks ticks_at(double lo, double hi, double step);

/// A round length (1, 2 or 5 times a power of ten) at most `length`.
double round_length(double length);

}  // namespace rockfdem::plots
