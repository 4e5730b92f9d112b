// bench_critical_dt: the cost of one stability-limit computation
// (Engine::critical_dt after a stage change: the element bound and the
// Lanczos iteration of stable_dt.cpp), which the tunnel pays at the start of
// each explicit stage.
//
//   bench_critical_dt [--cells N] [--threads T] [--repeats R]
//
// A 1 x 1 m square of 2 N^2 triangles (default N = 460: 423,200 triangles,
// 1,269,600 nodes, 633,880 crack elements, near the tunnel's 420k) of the
// benchmark rock, crack elements on every interior edge. Each repeat
// changes the local damping (which invalidates the cached limit) and times
// critical_dt(). Prints the command line, the model's sizes, the limit of
// each repeat (the same bits for any thread count) and the fastest and
// median seconds per call.
//
//   +--------+
//   |/|/|/|/ |  N x N cells, each split in two
//   +--------+
#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "bench_main.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/fdem/structured_mesh.hpp"

using namespace rockfdem;

int main(int argc, char** argv) {
  int cells = 460, threads = 2, repeats = 5;
  if (!bench::read_options(argc, argv,
                           {{"--cells", &cells}, {"--threads", &threads}, {"--repeats", &repeats}},
                           "bench_critical_dt [--cells N] [--threads T] [--repeats R]"))
    return 2;
  return bench::run_guarded([&] {
    fdem::RectangleSpec spec;
    spec.nx = spec.ny = cells;
    spec.width = spec.height = 1.0;
    fdem::ModelInput in = fdem::structured_rectangle(spec, fdem::benchmark_rock());
    in.threads = threads;
    fdem::Engine e(in);
    std::printf("%zu triangles, %zu nodes, %zu crack elements, %d threads\n", e.n_triangles(),
                e.n_nodes(), e.n_cracks(), threads);
    std::vector<double> seconds;
    for (int r = 0; r < repeats; ++r) {
      fdem::DampingSettings damping;
      damping.local = 0.1 * (r % 3 + 1);
      e.set_damping(damping);
      const double t0 = omp_get_wtime();
      const double limit = e.critical_dt();
      seconds.push_back(omp_get_wtime() - t0);
      std::printf("local damping %.1f: critical_dt %.17g s in %.3f s\n", damping.local, limit,
                  seconds.back());
    }
    std::sort(seconds.begin(), seconds.end());
    std::printf("per call: fastest %.3f s, median %.3f s\n", seconds.front(),
                seconds[seconds.size() / 2]);
    return 0;
  });
}
