// bench_stability: which time steps, penalties, element shapes and rotations
// stay bounded, and with what energy error.
//
//   bench_stability [--steps N]
//
// Each case is an 8 x 8-cell specimen with crack elements on every interior
// edge, free, undamped, started with small random velocities (plus a rigid
// spin of about one radian over the run for the rotation cases). The time
// step is factor * critical_dt (forced above 1). Energy error: largest
// |E - E0| / E0 over the run with the central-difference energy
// E_n = 1/2 sum m v(n-1/2).v(n+1/2) + U(x_n), U = strain + crack energy,
// which the scheme conserves exactly for a linear system (the plain
// half-step kinetic energy would wobble by O((omega dt)^2) in the stiffest
// modes that random velocities excite).
// Outcome: "bounded", or the step at which the engine stopped the run
// (NumericalError: inverted triangle, non-finite value, or growing velocity
// reversal), or "grew" when the energy rose tenfold without being stopped.
//
//   mesh "regular": right isosceles triangles (45 degrees)
//   mesh "sliver":  cells 11.4:1, smallest angle 5 degrees
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "rockfdem/fdem/constants.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/fdem/structured_mesh.hpp"

using namespace rockfdem;

struct Case {
  double factor, penalty;  // penalty in units of E
  bool sliver, spin;
};

struct Outcome {
  std::string what;
  double energy_error = 0;
  double critical_dt = 0;
};

fdem::Engine make_engine(const Case& c) {
  fdem::Material m = fdem::benchmark_rock();
  m.normal_penalty = m.tangential_penalty = c.penalty * m.young;
  fdem::RectangleSpec spec;
  spec.nx = spec.ny = 8;
  spec.width = 0.08;
  spec.height = c.sliver ? 0.08 * std::tan(5 * fdem::kPi / 180) : 0.08;
  return fdem::Engine(fdem::structured_rectangle(spec, m));
}

/// Steps once and returns E_n (see above) of the state before the step.
double step_with_energy(fdem::Engine& e) {
  const double potential = e.strain_energy() + e.crack_energy();
  const std::vector<double> before = e.velocities();
  e.step();
  const auto& after = e.velocities();
  const auto& m = e.node_mass();
  double kinetic = 0;
  for (std::size_t i = 0; i < before.size(); ++i) kinetic += 0.5 * m[i / 2] * before[i] * after[i];
  return kinetic + potential;
}

Outcome run_case(const Case& c, long steps) {
  fdem::Engine e = make_engine(c);
  Outcome out;
  out.critical_dt = e.critical_dt();
  e.set_dt(c.factor * out.critical_dt, fdem::DtCheck::kForce);
  const double spin = c.spin ? 1.0 / (steps * e.dt()) : 0.0;  // about 1 rad over the run
  std::mt19937 rng(11);
  // Small enough that even 1000 E penalties stay below the strengths.
  std::uniform_real_distribution<double> noise(-2e-3, 2e-3);
  const auto& p = e.positions();
  for (std::size_t n = 0; n < e.n_nodes(); ++n) {
    const double x = p[2 * n] - 0.04, y = p[2 * n + 1];
    e.set_node_state(n, p[2 * n], p[2 * n + 1], -spin * y + noise(rng), spin * x + noise(rng));
  }
  out.what = "bounded";
  try {
    const double e0 = step_with_energy(e);
    for (long i = 1; i < steps; ++i) {
      if (i % 10 != 0) {
        e.step();
      } else {
        const double err = std::fabs(step_with_energy(e) - e0) / e0;
        out.energy_error = std::max(out.energy_error, err);
        if (err > 10) {
          out.what = "grew (step " + std::to_string(e.step_count()) + ")";
          break;
        }
      }
    }
  } catch (const NumericalError&) {
    out.what = "stopped at step " + std::to_string(e.step_count());
  }
  if (e.broken_counts().total() > 0)
    out.what += ", " + std::to_string(e.broken_counts().total()) + " broken";
  return out;
}

int main(int argc, char** argv) {
  long steps = 2000;
  std::printf("command:");
  for (int i = 0; i < argc; ++i) std::printf(" %s", argv[i]);
  std::printf("\n");
  for (int i = 1; i + 1 < argc; i += 2)
    if (std::string(argv[i]) == "--steps") steps = std::atol(argv[i + 1]);
  std::printf("%-7s %-8s %-8s %-5s %-12s %-12s %s\n", "factor", "penalty", "mesh", "spin",
              "critical_dt", "energy_err", "outcome");
  for (bool sliver : {false, true})
    for (bool spin : {false, true})
      for (double penalty : {1.0, 10.0, 100.0, 1000.0})
        for (double factor : {0.1, 0.5, 0.9, 1.0, 1.05, 1.2}) {
          const Case c{factor, penalty, sliver, spin};
          const Outcome o = run_case(c, steps);
          std::printf("%-7.2f %-8.0f %-8s %-5s %-12.4g %-12.3g %s\n", factor, penalty,
                      sliver ? "sliver" : "regular", spin ? "yes" : "no", o.critical_dt,
                      o.energy_error, o.what.c_str());
        }
  return 0;
}
