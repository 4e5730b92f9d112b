// bench_contact: cost of contact while cracks keep breaking and fragments
// stay pressed together (the default tunnel after heavy fracture).
//
//   bench_contact [--triangles N] [--steps S] [--threads T] [--velocity V]
//                 [--confinement P] [--buffer F] [--report-every K]
//
// The UCS specimen of bench_ucs (50 x 100 mm, crack elements on every
// interior edge, 10% viscous damping, rough platens closing at V m/s each)
// with a confining pressure P [MPa] on both sides (default 20). The
// confinement keeps the fragments in contact, and the specimen goes on
// breaking for thousands of steps after the peak, a few crack elements a
// step: the situation in which a broad phase that starts again from
// scratch at every breakage costs most. A buffer F > 0 sets the contact
// buffer to F x the mean edge length (default 0: the engine's default).
//
// Prints the command line, counts, then every K steps: crack elements
// broken in the interval, the contact share of the step time, detections
// and local updates per 1000 steps, candidates, pairs, touching pairs and
// triangle-steps per second; at the end the totals and the state hash
// (equal hashes = bit-identical runs).
//
//        v platen
//      +-------+
//  P ->|/\/\/\/|<- P
//      |\/\/\/\|
//      +-------+
//        ^ platen
#include <omp.h>

#include <cmath>
#include <cstdio>

#include "bench_main.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "ucs_setup.hpp"

using namespace rockfdem;

namespace {

/// Mean triangle edge length (each interior edge counted twice, as the
/// engine does).
double mean_edge(const fdem::ModelInput& in) {
  double sum = 0;
  for (const auto& t : in.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      sum += std::hypot(in.x[b] - in.x[a], in.y[b] - in.y[a]);
    }
  return sum / (3.0 * in.triangles.size());
}

}  // namespace

int main(int argc, char** argv) {
  // 1. Options.
  long n_tri = 8800, steps = 20000, report = 1000;
  int threads = 0;
  double velocity = 1.0, confinement = 20.0, buffer = 0.0;
  const bool ok =
      bench::read_options(argc, argv,
                          {{"--triangles", &n_tri},
                           {"--steps", &steps},
                           {"--threads", &threads},
                           {"--velocity", &velocity},
                           {"--confinement", &confinement},
                           {"--buffer", &buffer},
                           {"--report-every", &report}},
                          "bench_contact [--triangles N] [--steps S] [--threads T] [--velocity V] "
                          "[--confinement MPa] [--buffer F] [--report-every K]");
  if (!ok) return 2;
  if (report <= 0) report = steps;
  return bench::run_guarded([&] {
    // 2. The confined specimen with contact.
    const fdem::RectangleSpec grid = fdem::ucs_grid(0.05, 0.1, n_tri);
    fdem::ModelInput in = fdem::ucs_specimen(grid, bench::ucs_rock(), velocity);
    for (int tag : {fdem::kTagLeft, fdem::kTagRight}) {
      fdem::BoundaryCondition side;
      side.tag = tag;
      side.pressure = confinement * 1e6;
      in.boundary_conditions.push_back(side);
    }
    in.threads = threads;
    in.contact.enabled = true;
    in.contact.buffer = buffer * mean_edge(in);
    fdem::Engine engine(in);
    std::printf("triangles %zu nodes %zu cracks %zu threads %d\n", engine.n_triangles(),
                engine.n_nodes(), engine.n_cracks(), engine.threads());
    std::printf("dt %.6g s, confinement %.4g MPa, buffer %.4g x mean edge (0: default)\n",
                engine.dt(), confinement, buffer);
    // 3. The time loop, one report per interval.
    const double t0 = omp_get_wtime();
    long broken_before = 0;
    for (long done = 0; done < steps;) {
      const long n = std::min(report, steps - done);
      const auto ph0 = engine.phase_times();
      const auto c0 = engine.contact_counters();
      const double t_interval = omp_get_wtime();
      engine.run(n);
      const double interval = omp_get_wtime() - t_interval;
      const auto ph1 = engine.phase_times();
      const auto c1 = engine.contact_counters();
      done += n;
      const long broken = engine.broken_counts().total();
      const double contact = ph1.contact - ph0.contact;
      const double all =
          ph1.triangles - ph0.triangles + ph1.cracks - ph0.cracks + contact + ph1.nodes - ph0.nodes;
      std::printf(
          "step %6ld broken %5ld (+%4ld) contact %4.1f%% detections/1000 %6.1f updates/1000 "
          "%6.1f candidates %5ld pairs %6ld touching %5ld triangle-steps/s %.4g\n",
          done, broken, broken - broken_before, 100 * contact / all,
          1000.0 * (c1.detections - c0.detections) / n, 1000.0 * (c1.updates - c0.updates) / n,
          c1.candidates, c1.pairs, c1.touching, double(engine.n_triangles()) * n / interval);
      broken_before = broken;
    }
    // 4. Totals.
    const double wall = omp_get_wtime() - t0;
    const auto ph = engine.phase_times();
    const auto c = engine.contact_counters();
    std::printf("steps %ld wall %.3f s triangle-steps/s %.4g\n", steps, wall,
                double(engine.n_triangles()) * steps / wall);
    std::printf("phases: triangles %.3f s cracks %.3f s contact %.3f s nodes %.3f s\n",
                ph.triangles, ph.cracks, ph.contact, ph.nodes);
    std::printf("contact: detections %ld updates %ld steps with pairs %ld kernel %s\n",
                c.detections, c.updates, c.steps_with_pairs, c.kernel);
    std::printf("broken %ld\n", engine.broken_counts().total());
    std::printf("state_hash %s\n", engine.state_hash().c_str());
    return 0;
  });
}
