// The Mohr-Coulomb closed form for a circular opening under hydrostatic
// stress, and the input checks of the plastic continuum (no deal.II here).
#include <cmath>
#include <string>

#include "rockfdem/error.hpp"
#include "rockfdem/insitu/plastic.hpp"

namespace rockfdem::insitu {

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180;

void require(bool ok, const std::string& key, double value, const std::string& allowed) {
  if (!ok)
    throw InputError("insitu mohr_coulomb: " + key + " = " + std::to_string(value) + ": " +
                     allowed);
}

}  // namespace

void validate(const PlasticSpec& p) {
  require(p.rock.cohesion >= 0, "cohesion", p.rock.cohesion, "must be >= 0 [Pa]");
  require(p.rock.friction_deg > 0 && p.rock.friction_deg < 90, "friction_angle",
          p.rock.friction_deg, "must lie in (0, 90) degrees");
  require(p.rock.dilation_deg >= 0 && p.rock.dilation_deg <= p.rock.friction_deg, "dilation_angle",
          p.rock.dilation_deg, "must lie in [0, friction_angle] degrees");
  if (p.residual) {
    const ResidualStrength& r = *p.residual;
    require(r.cohesion >= 0 && r.cohesion <= p.rock.cohesion, "residual_cohesion", r.cohesion,
            "must lie in [0, cohesion] [Pa]");
    require(r.friction_deg > 0 && r.friction_deg >= p.rock.dilation_deg &&
                r.friction_deg <= p.rock.friction_deg,
            "residual_friction_angle", r.friction_deg,
            "must lie in [dilation_angle, friction_angle] degrees and be > 0");
    require(r.softening_strain >= 0 && std::isfinite(r.softening_strain), "softening_strain",
            r.softening_strain, "must be >= 0 [-] (0: elastic-brittle-plastic)");
  }
  require(p.max_increment > 0 && p.max_increment <= 1, "max_increment", p.max_increment,
          "must lie in (0, 1]");
  require(p.tolerance > 0 && p.tolerance < 1e-3, "tolerance", p.tolerance, "must lie in (0, 1e-3)");
  require(!p.release.empty(), "release (count)", 0, "needs at least one lambda in (0, 1]");
  double previous = 0;
  for (const double l : p.release) {
    require(l > previous && l <= 1, "release", l, "must increase strictly within (0, 1]");
    previous = l;
  }
}

// Compression positive, displacement inward. In the plastic ring a <= r <=
// R the stresses are Salencon's at the plastic zone's strength (Brown et al.
// 1983 with a residual one): sigma_r = (pi + B) (r/a)^(k-1) - B with
// B = sigma_cm / (k - 1) and sigma_theta = k sigma_r + sigma_cm, k and
// sigma_cm the residual ones; R where sigma_r reaches the peak's p_cr. The
// flow rule (g = sigma_theta - K_psi sigma_r) gives eps_r^p + K_psi
// eps_theta^p = 0; with eps_r = du/dr, eps_theta = u/r and the elastic
// strains from Hooke's law on sigma - p0 (the plastic strain is then whatever
// the rest is, the jump at R of a brittle drop included; exact when sigma_z
// stays the intermediate stress), du/dr + K_psi u / r = eps_r^e + K_psi
// eps_theta^e, integrated from u(R) = (p0 - p_cr) R / 2G inwards.
PlasticRingSolution plastic_ring(const PlasticRingCase& c) {
  PlasticRingSolution s;
  const auto strength = [](double cohesion, double phi_deg, double& k, double& sigma_cm) {
    const double sp = std::sin(phi_deg * kDeg);
    k = (1 + sp) / (1 - sp);
    sigma_cm = 2 * cohesion * std::cos(phi_deg * kDeg) / (1 - sp);
  };
  strength(c.strength.cohesion, c.strength.friction_deg, s.k, s.sigma_cm);
  if (c.residual)
    strength(c.residual->cohesion, c.residual->friction_deg, s.k_r, s.sigma_cr);
  else
    s.k_r = s.k, s.sigma_cr = s.sigma_cm;
  const double sd = std::sin(c.strength.dilation_deg * kDeg);
  const double kpsi = (1 + sd) / (1 - sd), k = s.k_r;
  s.critical_pressure = (2 * c.p0 - s.sigma_cm) / (1 + s.k);
  const double G = c.E / (2 * (1 + c.nu));
  if (c.pi >= s.critical_pressure) {
    s.plastic_radius = c.a;
    s.wall_displacement = (c.p0 - c.pi) * c.a / (2 * G);
    return s;
  }
  const double B = s.sigma_cr / (k - 1), A = c.pi + B;
  const double rho = std::pow((s.critical_pressure + B) / A, 1 / (k - 1));
  s.plastic_radius = rho * c.a;
  const double u_R = (c.p0 - s.critical_pressure) * s.plastic_radius / (2 * G);
  const double nu = c.nu;
  const double C1 = (1 - nu) - nu * k + kpsi * ((1 - nu) * k - nu);
  const double integral =  // int_a^R (s/a)^K_psi f(s) ds, times 2G / a
      A * C1 * (std::pow(rho, kpsi + k) - 1) / (kpsi + k) -
      (B + c.p0) * (1 - 2 * nu) * (1 + kpsi) * (std::pow(rho, kpsi + 1) - 1) / (kpsi + 1);
  s.wall_displacement = std::pow(rho, kpsi) * u_R - c.a / (2 * G) * integral;
  return s;
}

// Lame outside R (sigma_r = p0 - (p0 - p_R)(R/r)^2, p_R = p_cr or pi when
// elastic), Salencon/Brown inside.
double plastic_ring_radial_stress(const PlasticRingCase& c, double r) {
  const PlasticRingSolution s = plastic_ring(c);
  const double R = s.plastic_radius;
  if (r >= R) {
    const double pR = R > c.a ? s.critical_pressure : c.pi;
    return c.p0 - (c.p0 - pR) * (R / r) * (R / r);
  }
  const double B = s.sigma_cr / (s.k_r - 1);
  return (c.pi + B) * std::pow(r / c.a, s.k_r - 1) - B;
}

}  // namespace rockfdem::insitu
