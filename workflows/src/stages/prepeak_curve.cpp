#include "stages/prepeak_curve.hpp"

#include <algorithm>

namespace rockfdem::workflows {

PrePeakCurve::PrePeakCurve(int capacity)
    : strain_(static_cast<std::size_t>(capacity)),
      stress_(static_cast<std::size_t>(capacity)),
      capacity_(capacity) {}

void PrePeakCurve::add(double strain, double stress) {
  if (seen_++ % stride_ != 0) return;
  // Full, the kept readings are 0, s, ..., (capacity - 1) s and this one is
  // capacity s: with an even capacity it is kept at the doubled stride too.
  if (count_ == capacity_) halve();
  strain_[count_] = strain;
  stress_[count_] = stress;
  ++count_;
}

void PrePeakCurve::halve() {
  for (int i = 0; 2 * i < count_; ++i) {
    strain_[i] = strain_[2 * i];
    stress_[i] = stress_[2 * i];
  }
  count_ = (count_ + 1) / 2;
  stride_ *= 2;
}

std::optional<double> PrePeakCurve::modulus(double peak_stress, double peak_strain) const {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = 0; i < count_ && strain_[i] <= peak_strain; ++i) {
    const double x = strain_[i], y = stress_[i];
    if (y < 0.2 * peak_stress || y > 0.6 * peak_stress) continue;
    n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double d = n * sxx - sx * sx;
  if (n < 5 || d <= 0) return std::nullopt;
  return (n * sxy - sx * sy) / d;
}

nlohmann::json PrePeakCurve::state() const {
  return {{"stride", stride_},
          {"seen", seen_},
          {"strain", std::vector<double>(strain_.begin(), strain_.begin() + count_)},
          {"stress", std::vector<double>(stress_.begin(), stress_.begin() + count_)}};
}

void PrePeakCurve::restore(const nlohmann::json& s) {
  const auto strain = s.at("strain").get<std::vector<double>>();
  const auto stress = s.at("stress").get<std::vector<double>>();
  count_ = static_cast<int>(std::min(strain.size(), stress.size()));
  if (count_ > capacity_) count_ = capacity_;
  std::copy(strain.begin(), strain.begin() + count_, strain_.begin());
  std::copy(stress.begin(), stress.begin() + count_, stress_.begin());
  stride_ = s.at("stride").get<long>();
  seen_ = s.at("seen").get<long>();
}

}  // namespace rockfdem::workflows
