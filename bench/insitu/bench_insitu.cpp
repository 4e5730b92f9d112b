// bench_insitu: what the implicit in-situ stage costs and how accurate it is.
//
//   bench_insitu [--levels N] [--tunnel-size H]... [--skip-direct]
//
// 1. The seed tunnel (scenes/tunnel-seed-oneshot.toml: horseshoe 11.3 x 8.8 m,
//    200 mm lining, 80 m box, wall size H = 0.35 m (the scene's) and 0.1 m
//    unless --tunnel-size is given (repeatable), E = 3 GPa, lining
//    installed at alpha = 0.01), alpha = 1, 0.5, 0.2, 0.1, 0.05, 0.01 with
//    the automatic solver: time per alpha, iterations, and the process's
//    peak memory (getrusage) after the stage.
// 2. Kirsch (circular hole a = 5 m, 100 m box, the seed's 18.2 / 11.4 MPa,
//    exact Kirsch tractions, core removed): for N gmsh refinements (size at
//    the wall 0.8 m, halved each level, ten times that at the box), both
//    solvers: triangles, dofs, assembly, solve and total time, CG
//    iterations, relative L2 stress error over a <= r <= 5a.
//
//        +---------- box ----------+
//        |          .--.           |   sH <-->   sV (vertical)
//        |         ( oo )  core    |
//        |          '--'           |
//        +-------------------------+
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "rockfdem/error.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/build.hpp"

namespace {

using namespace rockfdem;

double peak_rss_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;  // Linux: kilobytes
}

void kirsch_table(int levels, bool with_direct) {
  const double a = 5.0;
  insitu::InsituSpec spec;
  spec.far_field.sH = 18.2e6;
  spec.far_field.sV = 11.4e6;
  spec.materials.rock = insitu::ElasticMaterial{10e9, 0.25};
  spec.materials.core = spec.materials.rock;
  spec.loading = insitu::BoundaryLoading::kKirschExact;
  spec.kirsch_radius = a;
  spec.alphas = {0.0};
  insitu::KirschCase k{a, 18.2e6, 11.4e6, 0.0, 10e9, 0.25};

  std::printf("\n2. Kirsch, a = 5 m, 100 m box, exact tractions, alpha = 0\n");
  std::printf("%7s %9s %9s %8s %-7s %5s %8s %8s %8s %8s %8s %11s %9s\n", "h_near", "triangles",
              "rock", "dofs", "solver", "iter", "setup s", "assem s", "solve s", "post s",
              "total s", "stress L2 %", "wall ur %");
  double h = 0.8;
  for (int level = 0; level < levels; ++level, h *= 0.5) {
    mesh::MeshSpec ms;
    ms.kind = mesh::ModelKind::kTunnel;
    ms.tunnel.shape = mesh::TunnelShape::kCircular;
    ms.tunnel.radius = a;
    ms.domain.width = ms.domain.height = 100;
    ms.size.size_near = h;
    ms.size.size_far = 10 * h;
    const mesh::Mesh m = mesh::build_mesh(ms);
    for (const auto kind : {insitu::LinearSolver::kAmgCg, insitu::LinearSolver::kDirect}) {
      if (kind == insitu::LinearSolver::kDirect && !with_direct) continue;
      spec.solver.kind = kind;
      const insitu::InsituField f = insitu::solve_insitu(m, spec).at(0);
      const insitu::KirschComparison c = insitu::compare_kirsch(m, f, k);
      std::printf("%7.3f %9zu %9zu %8zu %-7s %5d %8.3f %8.3f %8.3f %8.3f %8.3f %11.4f %9.4f\n", h,
                  m.n_triangles(), f.n_cells, f.n_dofs,
                  kind == insitu::LinearSolver::kDirect ? "direct" : "amg-cg", f.iterations,
                  f.setup_seconds, f.assembly_seconds, f.solve_seconds, f.postprocess_seconds,
                  f.total_seconds, 100 * c.stress_rel_l2, 100 * c.wall_ur_rel_l2);
      std::fflush(stdout);
    }
  }
}

void default_tunnel(double size_near) {
  mesh::MeshSpec ms;  // defaults: horseshoe 11.3 x 8.8
  ms.tunnel.lining_thickness = 0.2;
  ms.domain.width = ms.domain.height = 80;
  ms.size.size_near = size_near;
  ms.size.size_far = 5.0;
  ms.size.grading_distance = 25.0;
  const auto t0 = std::chrono::steady_clock::now();
  const mesh::Mesh m = mesh::build_mesh(ms);
  const double mesh_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  insitu::InsituSpec spec;
  spec.far_field.sH = 18.2e6;
  spec.far_field.sV = 11.4e6;
  spec.materials.rock = insitu::ElasticMaterial{3e9, 0.25};
  spec.materials.core = spec.materials.rock;
  spec.materials.lining = insitu::ElasticMaterial{5e8, 0.3};
  spec.lining.active = true;
  spec.lining.install_alpha = 0.01;
  spec.alphas = {1.0, 0.5, 0.2, 0.1, 0.05, 0.01};

  std::printf(
      "\n1. Default tunnel: %zu triangles, %zu vertices, size_near %.2f m "
      "(mesh %.2f s, peak RSS before the stage %.0f MiB)\n",
      m.n_triangles(), m.n_vertices(), size_near, mesh_s, peak_rss_mib());
  const auto t1 = std::chrono::steady_clock::now();
  const auto fields = insitu::solve_insitu(m, spec);
  const double stage_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  std::printf("%s", insitu::timing_table(fields).c_str());
  std::printf("in-situ stage: %.3f s for %zu alphas, peak RSS %.0f MiB\n", stage_s, fields.size(),
              peak_rss_mib());
}

}  // namespace

int main(int argc, char** argv) {
  rockfdem::insitu::ScopedParallelInit parallel(argc, argv);
  int levels = 5;
  std::vector<double> tunnel_sizes;
  bool with_direct = true;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--levels") && i + 1 < argc)
      levels = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--tunnel-size") && i + 1 < argc)
      tunnel_sizes.push_back(std::atof(argv[++i]));
    else if (!std::strcmp(argv[i], "--skip-direct"))
      with_direct = false;
    else {
      std::fprintf(stderr, "usage: %s [--levels N] [--tunnel-size H] [--skip-direct]\n", argv[0]);
      return 2;
    }
  }
  std::printf("command:");
  for (int i = 0; i < argc; ++i) std::printf(" %s", argv[i]);
  char host[256] = "?";
  gethostname(host, sizeof host);
  std::printf("\nhost: %s, %ld online cores; deal.II threads: 1 (TBB); Release build\n", host,
              sysconf(_SC_NPROCESSORS_ONLN));
  try {
    // The tunnel first: its peak memory is then its own, not the largest
    // Kirsch factorisation's.
    if (tunnel_sizes.empty()) tunnel_sizes = {0.35, 0.1};
    for (const double h : tunnel_sizes) default_tunnel(h);
    kirsch_table(levels, with_direct);
  } catch (const rockfdem::InputError& e) {
    std::fprintf(stderr, "bad input: %s\n", e.what());
    return 2;
  } catch (const rockfdem::NumericalError& e) {
    std::fprintf(stderr, "numerical failure: %s\n", e.what());
    return 3;
  }
  return 0;
}
