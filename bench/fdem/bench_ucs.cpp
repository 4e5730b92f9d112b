// bench_ucs: throughput of the fracturing UCS test.
//
//   bench_ucs [--triangles N] [--steps S] [--threads T] [--velocity V]
//             [--report-every K] [--contact 0|1] [--memory 0|1]
//
// A 50 x 100 mm specimen on the structured mesh (about N triangles, crack
// elements on every interior edge) is loaded by rough platens moving towards
// each other at V m/s each for S steps of the automatic dt. Prints the
// command line, counts, wall time of the time loop, triangle-steps per
// second, the state hash (equal hashes = bit-identical runs), broken counts
// by mode and the axial stress history every K steps, with each interval's
// throughput and contact counters (--contact 1 enables contact: the cost of
// contact before and after fracture). --memory 1 prints the engine's arrays
// with their bytes per triangle after the run (Engine::memory_breakdown).
//
//        v platen (prescribed velocity, x fixed)
//      +-------+
//      |/\/\/\/|   every triangle its own body, joined by crack elements
//      |\/\/\/\|
//      +-------+
//        ^ platen
#include <omp.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "bench_main.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "ucs_setup.hpp"

using namespace rockfdem;

namespace {

/// The engine's non-empty arrays in bytes per triangle, and their total.
void print_memory(const fdem::Engine& e) {
  const double nt = double(e.n_triangles());
  for (const fdem::MemoryPart& p : e.memory_breakdown())
    if (p.bytes > 0)
      std::printf("memory %-28s %8.1f B/triangle\n", p.name.c_str(), double(p.bytes) / nt);
  std::printf("memory total %.1f B/triangle\n", double(e.memory_bytes()) / nt);
}

}  // namespace

int main(int argc, char** argv) {
  long n_tri = 33000, steps = 10000, report = 0;
  int threads = 0, contact = 0, memory = 0;
  double velocity = 1.0;  // strain rate 20/s: peak near step 6000, post-peak by 10^4
  if (!bench::read_options(argc, argv,
                           {{"--triangles", &n_tri},
                            {"--steps", &steps},
                            {"--threads", &threads},
                            {"--velocity", &velocity},
                            {"--contact", &contact},
                            {"--memory", &memory},
                            {"--report-every", &report}},
                           "bench_ucs [--triangles N] [--steps S] [--threads T] [--velocity V] "
                           "[--report-every K] [--contact 0|1] [--memory 0|1]"))
    return 2;
  return bench::run_guarded([&] {
    const fdem::RectangleSpec grid = fdem::ucs_grid(0.05, 0.1, n_tri);
    fdem::ModelInput in = fdem::ucs_specimen(grid, bench::ucs_rock(), velocity);
    in.threads = threads;
    in.contact.enabled = contact != 0;
    fdem::Engine engine(in);
    std::printf("triangles %zu nodes %zu cracks %zu threads %d\n", engine.n_triangles(),
                engine.n_nodes(), engine.n_cracks(), engine.threads());
    std::printf("dt %.6g s (critical %.6g s), strain rate %.4g 1/s, memory %.0f B/triangle\n",
                engine.dt(), engine.critical_dt(), 2 * velocity / 0.1,
                double(engine.memory_bytes()) / engine.n_triangles());
    double peak = 0;
    const double t0 = omp_get_wtime();
    for (long done = 0; done < steps;) {
      const long n = report > 0 ? std::min(report, steps - done) : steps - done;
      const double t_interval = omp_get_wtime();
      const auto before = engine.phase_times();
      engine.run(n);
      const double interval = omp_get_wtime() - t_interval;
      const double rate = double(engine.n_triangles()) * n / interval;
      const auto after = engine.phase_times();
      const double shares[4] = {after.triangles - before.triangles, after.cracks - before.cracks,
                                after.contact - before.contact, after.nodes - before.nodes};
      done += n;
      // The upper platen pushes down on the specimen: compression positive.
      const double stress = -engine.boundary_force(fdem::kTagTop)[1] / 0.05;
      peak = std::max(peak, stress);
      if (report > 0) {
        const auto b = engine.broken_counts();
        const auto c = engine.contact_counters();
        std::printf(
            "step %ld strain %.4e stress %.4g MPa broken %ld triangle-steps/s %.4g"
            " phases tri/crack/contact/node %.2f/%.2f/%.2f/%.2f s"
            " contact candidates %ld pairs %ld touching %ld detections %ld\n",
            done, 2 * velocity * engine.time() / 0.1, stress / 1e6, b.total(), rate, shares[0],
            shares[1], shares[2], shares[3], c.candidates, c.pairs, c.touching, c.detections);
      }
    }
    const double wall = omp_get_wtime() - t0;
    const auto b = engine.broken_counts();
    const auto ph = engine.phase_times();
    std::printf("steps %ld wall %.3f s triangle-steps/s %.4g\n", steps, wall,
                double(engine.n_triangles()) * steps / wall);
    std::printf("phases: triangles %.3f s cracks %.3f s contact %.3f s nodes %.3f s\n",
                ph.triangles, ph.cracks, ph.contact, ph.nodes);
    const auto c = engine.contact_counters();
    std::printf("contact %s: steps with pairs %ld, skipped %ld, detections %ld\n",
                c.enabled ? "on" : "off", c.steps_with_pairs, c.steps_skipped, c.detections);
    std::printf("peak axial stress %.4g MPa\n", peak / 1e6);
    std::printf("broken mode_I %ld mode_II %ld mixed %ld\n", b.mode_I, b.mode_II, b.mixed);
    std::printf("state_hash %s\n", engine.state_hash().c_str());
    if (memory) print_memory(engine);
    return 0;
  });
}
