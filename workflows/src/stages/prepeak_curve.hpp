// A specimen's stress-strain curve kept at a bounded number of points, and
// the pre-peak modulus read from it: what a laboratory reports as E of a
// UCS test (the slope of the straight part of the curve before the peak).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

namespace rockfdem::workflows {

class PrePeakCurve {
 public:
  /// At most `capacity` points (even, at least 8), allocated here, never
  /// in the time loop.
  explicit PrePeakCurve(int capacity = 2048);
  /// One reading per step; every stride-th is kept. When the buffer is
  /// full every other point is dropped and the stride doubles, so the kept
  /// points always span the whole run at an even spacing in steps.
  void add(double strain, double stress);
  /// The least-squares slope of stress against strain over the kept points
  /// up to `peak_strain` whose stress lies within [0.2, 0.6] of
  /// `peak_stress` (the straight part: above the platens' seating, below
  /// the cracking that bends the curve towards the peak; the fit, not a
  /// secant, so a lag of the stress behind the nominal strain does not
  /// lower it); none with fewer than 5 such points.
  std::optional<double> modulus(double peak_stress, double peak_strain) const;
  nlohmann::json state() const;
  void restore(const nlohmann::json& s);

 private:
  void halve();
  std::vector<double> strain_, stress_;
  int capacity_;
  int count_ = 0;
  long stride_ = 1, seen_ = 0;
};

}  // namespace rockfdem::workflows
