// bench_relaxation_engine: steps to equilibrium with each way of damping a
// quasi-static stage (reference sec. 8, "Accelerating quasi-static
// relaxation").
//
//   bench_relaxation_engine [--cells N] [--max-steps S] [--threads T]
//
// A 1 x 1 m plate of 2 N x N triangles (default N = 32) on rollers at the
// bottom and left, loaded at once by a traction on top, with mass scaling
// on, relaxed until the unbalanced-force ratio (Engine::
// unbalanced_force_ratio, checked every 10 steps) reaches 1e-3 and 1e-5,
// with: local damping 0.8 (the tunnel's default), local 0.5, kinetic
// damping alone, kinetic + local 0.3. Three models:
//   elastic    no crack elements, 1 MPa compression
//   joints     a crack element on every interior edge, 1 MPa compression
//              (intact: their penalties make the model stiffer and its
//              stiffest modes faster)
//   cracking   crack elements, Weibull strengths (m = 3, seed 1), 2 MPa
//              tension, which the damped approaches carry without a break;
//              undamped, the sudden load's overshoot (up to twice the
//              static stress) breaks the weakest elements and the plate
//              fails (at 3 MPa it fails with every damping)
// Prints the command line and a table: steps to each ratio ("-" when not
// reached within S steps, default 20000), kinetic-damping resets, broken
// crack elements, the final ratio and the energy balance's imbalance.
//
//        |  |  |  traction
//      +---------+
//   >o |         |
//   >o |         |
//      +---------+
//        o  o  o   rollers
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/fdem/structured_mesh.hpp"

using namespace rockfdem::fdem;

namespace {

struct Options {
  int cells = 32;
  long max_steps = 20000;
  int threads = 1;
};

enum class Model { kElastic, kJoints, kCracking };

const char* name(Model m) {
  return m == Model::kElastic ? "elastic" : m == Model::kJoints ? "joints" : "cracking";
}

struct Damping {
  const char* name;
  double local;
  bool kinetic;
};

ModelInput plate(const Options& o, Model model, const Damping& damping) {
  RectangleSpec spec;
  spec.width = spec.height = 1.0;
  spec.nx = spec.ny = o.cells;
  spec.fracture = model != Model::kElastic;
  Material rock = benchmark_rock();
  if (model == Model::kCracking) {
    rock.weibull_modulus = 3;
    rock.heterogeneity_seed = 1;
  }
  ModelInput in = structured_rectangle(spec, rock);
  in.boundary_conditions = rollers_with_top_traction(model == Model::kCracking ? 2e6 : -1e6);
  in.damping.local = damping.local;
  in.damping.kinetic = damping.kinetic;
  in.mass_scaling.enabled = true;
  in.threads = o.threads;
  return in;
}

std::string steps_or_dash(long s) { return s < 0 ? "-" : std::to_string(s); }

void run(const Options& o, Model model, const Damping& damping) {
  Engine e(plate(o, model, damping));
  long at_1e3 = -1, at_1e5 = -1;
  while (e.step_count() < o.max_steps) {
    e.run(10);
    const double r = e.unbalanced_force_ratio();
    if (at_1e3 < 0 && r <= 1e-3) at_1e3 = e.step_count();
    if (r <= 1e-5) {
      at_1e5 = e.step_count();
      break;
    }
  }
  std::printf("| %-8s | %-18s | %8s | %8s | %7ld | %6ld | %9.2e | %9.2e |\n", name(model),
              damping.name, steps_or_dash(at_1e3).c_str(), steps_or_dash(at_1e5).c_str(),
              e.kinetic_damping_resets(), e.broken_counts().total(), e.unbalanced_force_ratio(),
              e.energy_balance().imbalance());
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--cells")) {
      o.cells = std::atoi(argv[i + 1]);
    } else if (!std::strcmp(argv[i], "--max-steps")) {
      o.max_steps = std::atol(argv[i + 1]);
    } else if (!std::strcmp(argv[i], "--threads")) {
      o.threads = std::atoi(argv[i + 1]);
    } else {
      std::fprintf(stderr, "unknown option %s\n", argv[i]);
      return 2;
    }
  }
  std::printf("bench_relaxation_engine --cells %d --max-steps %ld --threads %d\n", o.cells,
              o.max_steps, o.threads);
  std::printf(
      "plate 1 x 1 m, %d triangles, mass scaling on; steps to the unbalanced-force "
      "ratio (checked every 10 steps)\n\n",
      2 * o.cells * o.cells);
  std::printf(
      "| model    | damping            | to 1e-3  | to 1e-5  | resets  | broken | "
      "ratio     | imbalance |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  const Damping dampings[] = {{"local 0.8", 0.8, false},
                              {"local 0.5", 0.5, false},
                              {"kinetic", 0.0, true},
                              {"kinetic + local 0.3", 0.3, true}};
  for (Model m : {Model::kElastic, Model::kJoints, Model::kCracking})
    for (const Damping& d : dampings) run(o, m, d);
  return 0;
}
