// Run time against error: the in-situ state of an elastic circular tunnel
// reached three ways, each compared with Kirsch over the annulus a <= r <= 5a.
//
//   build/bench/workflows/bench_relaxation [--near 0.3] [--box 100]
//
//   1. implicit: deal.II solves the open hole (alpha = 0) directly;
//   2. explicit from zero: the FDEM engine starts unstressed with the hole
//      open and the far-field traction on the box, and relaxes with local
//      damping (the classic dynamic-relaxation route);
//   3. explicit from the implicit hand-off (alpha = 0.2): the core is
//      removed in the engine and the model relaxes (what `rockfdem run` does);
//   2 and 3 are run on true masses, then with quasi-static mass scaling.
//
// For the explicit routes the table gives the time to reach each
// unbalanced-force ratio and the stress error there.
//
//        +----------- box -----------+
//        |            .-.            |  sH = 18.2 MPa, sV = 11.4 MPa
//        |           ( o ) a = 3 m   |  E = 5 GPa, nu = 0.25
//        |            '-'            |
//        +---------------------------+
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "rockfdem/coupling/fdem_model.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/build.hpp"

using namespace rockfdem;
using Clock = std::chrono::steady_clock;

namespace {

const double kA = 3, kE = 5e9, kNu = 0.25, kSH = 18.2e6, kSV = 11.4e6;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Relative L2 stress error over a <= r <= 5a, area weighted, rock triangles only.
double engine_stress_error(const fdem::Engine& e, const mesh::Mesh& m) {
  const insitu::KirschCase k{kA, kSH, kSV, 0, kE, kNu};
  double num = 0, den = 0;
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (m.zone[t] != mesh::kRock) continue;
    const auto& tri = m.triangles[t];
    const double cx = (m.x[tri[0]] + m.x[tri[1]] + m.x[tri[2]]) / 3;
    const double cy = (m.y[tri[0]] + m.y[tri[1]] + m.y[tri[2]]) / 3;
    const double r = std::hypot(cx, cy);
    if (r < kA || r > 5 * kA) continue;
    const double area = std::abs(mesh::signed_area(m, t));
    const auto s = e.triangle_stress(t);
    const insitu::Stress x = insitu::kirsch_stress(k, cx, cy);
    const double dxx = s[0] - x.sxx, dyy = s[1] - x.syy, dxy = s[2] - x.sxy;
    num += area * (dxx * dxx + dyy * dyy + 2 * dxy * dxy);
    den += area * (x.sxx * x.sxx + x.syy * x.syy + 2 * x.sxy * x.sxy);
  }
  return std::sqrt(num / den);
}

fdem::ModelInput model(const mesh::Mesh& m) {
  fdem::Material rock;
  rock.young = kE;
  rock.poisson = kNu;
  rock.density = 2700;
  rock.tensile_strength = rock.cohesion = 10 * kE;  // elastic: no crack elements anyway
  rock.gf_I = rock.gf_II = 1e9;
  fdem::ModelInput in =
      coupling::model_input(m, {{mesh::kRock, rock}, {mesh::kCore, rock}}, fdem::Plane::kStrain);
  const std::pair<int, std::array<double, 2>> sides[] = {{mesh::kLeft, {-1, 0}},
                                                         {mesh::kRight, {1, 0}},
                                                         {mesh::kBottom, {0, -1}},
                                                         {mesh::kTop, {0, 1}}};
  for (const auto& [tag, n] : sides) {
    fdem::BoundaryCondition bc;
    bc.tag = tag;
    bc.tx = -kSH * n[0];
    bc.ty = -kSV * n[1];
    in.boundary_conditions.push_back(bc);
  }
  return in;
}

void relax(fdem::Engine& e, const mesh::Mesh& m, const char* route, Clock::time_point t0) {
  e.set_damping({0.8, 0});
  double next = 1e-1;
  while (next >= 1e-5 && e.step_count() < 400000) {
    e.run(100);
    const double ratio = e.unbalanced_force_ratio();
    if (ratio < next) {
      std::printf("%-34s %10.0e %10ld %10.3f %12.4f%%\n", route, next, e.step_count(),
                  seconds_since(t0), 100 * engine_stress_error(e, m));
      next /= 10;
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  insitu::ScopedParallelInit parallel(argc, argv);
  double near = 0.3, box = 100;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--near")) near = std::stod(argv[i + 1]);
    if (!std::strcmp(argv[i], "--box")) box = std::stod(argv[i + 1]);
  }
  std::printf("# command: bench_relaxation --near %g --box %g   (threads %d)\n", near, box,
              omp_get_max_threads());
  mesh::MeshSpec spec;
  spec.tunnel.shape = mesh::TunnelShape::kCircular;
  spec.tunnel.radius = kA;
  spec.domain.width = spec.domain.height = box;
  spec.size.size_near = near;
  spec.size.size_far = box / 16;
  const mesh::Mesh m = mesh::build_mesh(spec);
  std::printf("# %zu triangles\n", m.n_triangles());
  std::printf("%-34s %10s %10s %10s %13s\n", "route", "ratio", "steps", "seconds", "stress error");

  insitu::InsituSpec is;
  is.far_field = {kSH, kSV, 0, {}};
  is.materials.rock = insitu::ElasticMaterial{kE, kNu};
  is.materials.core = insitu::ElasticMaterial{kE, kNu};
  is.alphas = {0.0};
  auto t0 = Clock::now();
  const std::vector<insitu::InsituField> fields = insitu::solve_insitu(m, is);
  const double implicit_seconds = seconds_since(t0);
  const insitu::KirschComparison c =
      insitu::compare_kirsch(m, fields.back(), {kA, kSH, kSV, 0, kE, kNu});
  std::printf("%-34s %10s %10s %10.3f %12.4f%%\n", "implicit (one solve)", "-", "-",
              implicit_seconds, 100 * c.stress_rel_l2);

  for (const bool scaled : {false, true}) {  // true masses, then quasi-static mass scaling
    const std::string tag = scaled ? ", mass-scaled" : "";
    {  // explicit from zero: hole open, far-field traction, no initial stress
      fdem::ModelInput in = model(m);
      in.mass_scaling.enabled = scaled;
      t0 = Clock::now();
      fdem::Engine e(in);
      for (std::size_t t = 0; t < m.n_triangles(); ++t)
        if (m.zone[t] != mesh::kRock) e.set_active(t, false);
      relax(e, m, ("from zero" + tag).c_str(), t0);
    }
    {  // explicit from the implicit hand-off at alpha = 0.2
      t0 = Clock::now();
      const std::vector<insitu::InsituField> handoff = insitu::solve_insitu(m, [&] {
        insitu::InsituSpec s = is;
        s.alphas = {1.0, 0.2};
        return s;
      }());
      fdem::ModelInput in = model(m);
      in.mass_scaling.enabled = scaled;
      coupling::apply_insitu(handoff.back(), in);
      in.materials[1].young *= 0.2;  // the core at alpha_h E (zone order: rock, core)
      fdem::Engine e(in);
      for (std::size_t t = 0; t < m.n_triangles(); ++t)
        if (m.zone[t] != mesh::kRock) e.set_active(t, false);
      relax(e, m, ("from hand-off a=0.2" + tag).c_str(), t0);
    }
  }
  return 0;
}
