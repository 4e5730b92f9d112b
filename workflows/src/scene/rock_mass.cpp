#include "rockfdem/workflows/rock_mass.hpp"

#include <cmath>
#include <tuple>

namespace rockfdem::workflows {

double mohr_coulomb_ucs(double c, double phi_deg) {
  const double phi = phi_deg * M_PI / 180;
  return 2 * c * std::cos(phi) / (1 - std::sin(phi));
}

RockMassFigures hoek_brown_constants(double mi, double gsi, double disturbance) {
  RockMassFigures f;
  f.mb = mi * std::exp((gsi - 100) / (28 - 14 * disturbance));
  f.s = std::exp((gsi - 100) / (9 - 3 * disturbance));
  f.a = 0.5 + (std::exp(-gsi / 15) - std::exp(-20.0 / 3)) / 6;
  return f;
}

double hoek_brown_sigma1(const RockMassFigures& f, double sigma_ci, double sigma3) {
  return sigma3 + sigma_ci * std::pow(f.mb * sigma3 / sigma_ci + f.s, f.a);
}

std::pair<double, double> mohr_coulomb_fit(const RockMassFigures& f, double sigma_ci,
                                           double sigma_3max) {
  // The Mohr-Coulomb line balancing the areas above and below the
  // Hoek-Brown curve over sigma_t < sigma3 < sigma3max (Hoek et al. 2002).
  const double mb = f.mb, s = f.s, a = f.a;
  const double s3n = sigma_3max / sigma_ci;
  const double k = 6 * a * mb * std::pow(s + mb * s3n, a - 1);
  const double den = (1 + a) * (2 + a);
  const double phi = std::asin(k / (2 * den + k)) * 180 / M_PI;
  const double c = sigma_ci * ((1 + 2 * a) * s + (1 - a) * mb * s3n) *
                   std::pow(s + mb * s3n, a - 1) / (den * std::sqrt(1 + k / den));
  return {c, phi};
}

double hoek_brown_tensile_strength(const RockMassFigures& f, double sigma_ci) {
  return f.s * sigma_ci / f.mb;
}

RockMassFigures rock_mass(const IntactRock& intact, double gsi, double disturbance,
                          double gamma_h) {
  RockMassFigures f = hoek_brown_constants(intact.mi, gsi, disturbance);
  const double mb = f.mb, s = f.s, a = f.a, ci = intact.ucs;
  f.sigma_cm =
      ci * (mb + 4 * s - a * (mb - 8 * s)) * std::pow(mb / 4 + s, a - 1) / (2 * (1 + a) * (2 + a));
  f.sigma_3max = f.sigma_cm * 0.47 * std::pow(f.sigma_cm / gamma_h, -0.94);
  std::tie(f.cohesion, f.friction_angle) = mohr_coulomb_fit(f, ci, f.sigma_3max);
  f.tensile_strength = hoek_brown_tensile_strength(f, ci);
  f.young = intact.young *
            (0.02 + (1 - disturbance / 2) / (1 + std::exp((60 + 15 * disturbance - gsi) / 11)));
  return f;
}

}  // namespace rockfdem::workflows
