// bench_checkpoint: size and speed of the engine's checkpoint.
//
//   bench_checkpoint [--triangles N] [--steps S] [--threads T] [--repeat R]
//
// The fracturing UCS of bench_ucs (about N triangles, platens at 1 m/s,
// contact on) runs S steps; its state is then saved R times to memory and
// loaded R times into a fresh engine built from the same input, and the best
// time of each is printed with the size. The restarted engine must show the
// same state hash, and again after 100 more steps on both.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "bench_main.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "ucs_setup.hpp"

using namespace rockfdem;

namespace {

/// Best wall time of r calls of f [s].
template <class F>
double best_of(int r, F&& f) {
  double best = 1e300;
  for (int i = 0; i < r; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  long n_tri = 33000, steps = 10000, threads = 0, repeat = 5;
  std::printf("command:");
  for (int i = 0; i < argc; ++i) std::printf(" %s", argv[i]);
  std::printf("\n");
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    long* value = a == "--triangles" ? &n_tri
                  : a == "--steps"   ? &steps
                  : a == "--threads" ? &threads
                  : a == "--repeat"  ? &repeat
                                     : nullptr;
    if (!value) {
      std::fprintf(stderr, "unknown option %s\n", a.c_str());
      return 2;
    }
    *value = std::atol(argv[i + 1]);
  }
  return bench::run_guarded([&] {
    fdem::ModelInput in =
        fdem::ucs_specimen(fdem::ucs_grid(0.05, 0.1, n_tri), bench::ucs_rock(), 1.0);
    in.threads = static_cast<int>(threads);
    in.contact.enabled = true;
    fdem::Engine engine(in);
    engine.run(steps);
    const auto c = engine.contact_counters();
    std::printf("triangles %zu nodes %zu cracks %zu threads %d steps %ld broken %ld pairs %ld\n",
                engine.n_triangles(), engine.n_nodes(), engine.n_cracks(), engine.threads(), steps,
                engine.broken_counts().total(), c.pairs);
    std::string bytes;
    const int r = static_cast<int>(std::max(1L, repeat));
    const double t_save = best_of(r, [&] {
      std::ostringstream out;
      engine.save_state(out);
      bytes = out.str();
    });
    fdem::Engine restarted(in);
    const double t_load = best_of(r, [&] {
      std::istringstream is(bytes);
      restarted.load_state(is);
    });
    const double t_fingerprint = best_of(r, [&] { (void)engine.model_fingerprint(); });
    const double mb = bytes.size() / 1e6;
    std::printf("checkpoint %zu B (%.0f B/triangle; engine arrays %.0f B/triangle)\n", bytes.size(),
                double(bytes.size()) / engine.n_triangles(),
                double(engine.memory_bytes()) / engine.n_triangles());
    std::printf(
        "save %.1f ms (%.0f MB/s), load %.1f ms (%.0f MB/s), fingerprint %.1f ms, "
        "best of %d, to and from memory\n",
        1e3 * t_save, mb / t_save, 1e3 * t_load, mb / t_load, 1e3 * t_fingerprint, r);
    const std::string h0 = engine.state_hash(), h1 = restarted.state_hash();
    engine.run(100);
    restarted.run(100);
    const bool same = h0 == h1 && engine.state_hash() == restarted.state_hash();
    std::printf("state_hash %s restarted %s, after 100 more steps %s: %s\n", h0.c_str(), h1.c_str(),
                engine.state_hash().c_str(), same ? "identical" : "DIFFERENT");
    return same ? 0 : 1;
  });
}
