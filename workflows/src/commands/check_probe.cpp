#include "commands/check_probe.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <thread>

#include "commands/commands.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/build.hpp"
#include "run/engine_setup.hpp"
#include "stages/platen_load.hpp"

namespace rockfdem::workflows {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// The 1-minute load average (Linux's /proc/loadavg); -1 where unknown.
double load_average() {
  std::ifstream f("/proc/loadavg");
  double load = -1;
  return f >> load ? load : -1;
}

double peak_rss_bytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) * 1024.0;  // Linux: kilobytes
}

// The implicit stage's hand-off without its solve: no in-situ stress or
// displacement, the core at the last alpha, and the triangles the implicit
// stage leaves out (excavated ground at alpha 0) inactive, as the run has them.
insitu::InsituField unstressed_handoff(const Scene& s, const mesh::Mesh& m) {
  insitu::InsituField f;
  f.alpha = s.insitu.alpha.back();
  f.stress.assign(m.n_triangles(), insitu::Stress{});
  f.active.assign(m.n_triangles(), 1);
  f.ux.assign(m.n_vertices(), 0.0);
  f.uy.assign(m.n_vertices(), 0.0);
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    const bool lining = m.zone[t] == mesh::kLining && s.insitu.lining_active;
    if (m.zone[t] != mesh::kRock && !lining && f.alpha <= 0) f.active[t] = 0;
  }
  return f;
}

// Enough steps to time (about 10 M triangle-steps, a second or two), a
// thousand at most: shorter probes on the shared machine read 0.5-2 times
// the steps' cost in the run that followed (docs/benchmarks.md).
long probe_steps(std::size_t triangles) {
  return std::clamp<long>(long(1e7 / double(std::max<std::size_t>(triangles, 1))), 20, 1000);
}

// Wall time per step of `steps` steps in three runs of about a third
// each: the middle one's. On a machine shared with other work one run can
// meet a burst of load (a probe of 177 steps read 3.44 ms per step where
// its run then took 2.77, docs/benchmarks.md); the median ignores one.
double median_step_seconds(fdem::Engine& engine, long steps) {
  std::array<double, 3> per_step{};
  long done = 0;
  for (int i = 0; i < 3; ++i) {
    const long n = i < 2 ? steps / 3 : steps - done;
    const Clock::time_point t0 = Clock::now();
    for (long k = 0; k < n; ++k) engine.step();
    per_step[std::size_t(i)] = seconds_since(t0) / double(n);
    done += n;
  }
  std::sort(per_step.begin(), per_step.end());
  return per_step[1];
}

}  // namespace

Probe probe_scene(const Scene& scene, const RunContext& ctx) {
  Probe p;
  p.threads = ctx.threads;
  const Clock::time_point t0 = Clock::now();
  mesh::MeshReport report;
  const mesh::Mesh m = keeping_threads(ctx, [&] { return mesh::build_mesh(scene.mesh, &report); });
  p.mesh_seconds = seconds_since(t0);
  p.triangles = m.n_triangles();
  p.fracture_triangles = std::size_t(std::count(m.fracture.begin(), m.fracture.end(), 1));
  p.min_altitude = report.min_altitude;

  const bool tunnel =
      scene.mesh.kind == mesh::ModelKind::kTunnel || scene.mesh.kind == mesh::ModelKind::kMshFile;
  fdem::ModelInput in = tunnel ? engine_input(scene, m, unstressed_handoff(scene, m), ctx.threads)
                               : specimen_model_input(scene, m, ctx.threads);
  const fdem::DampingSettings start_damping = in.damping;
  fdem::Engine engine = make_engine(in, scene, false);
  if (tunnel) {
    const insitu::InsituField f = unstressed_handoff(scene, m);
    for (std::size_t t = 0; t < m.n_triangles(); ++t)
      if (!f.active[t]) engine.set_active(t, false);
  }
  engine.step();  // the hand-off step, on the start's damping
  p.dt_start = engine.dt();
  if (tunnel) engine.set_damping(stage_damping(scene));
  p.dt_stages = engine.dt();
  p.rss_bytes = peak_rss_bytes();

  for (int k = 0; k < 5; ++k) engine.step();  // first-touch of the step's buffers, untimed
  p.steps = probe_steps(p.triangles);
  const double cpu0 = cpu_seconds();
  const Clock::time_point t0_steps = Clock::now();
  p.seconds_per_step = median_step_seconds(engine, p.steps);
  const double wall = seconds_since(t0_steps) * std::max(1, p.threads);
  if (wall > 0) p.cpu_share = (cpu_seconds() - cpu0) / wall;
  p.load_average = load_average();
  p.cores = int(std::thread::hardware_concurrency());

  engine.set_mass_scaling({false, 0.0});
  engine.set_damping(start_damping);
  p.critical_true = engine.critical_dt();
  return p;
}

std::string busy_machine_note(const Probe& p) {
  char text[256];
  if (p.cpu_share < 0.5) {
    std::snprintf(text, sizeof text,
                  "  note: the probe's steps got %.0f%% of %d %s time: other work shares this "
                  "machine, so the run-time figures read high for a quieter one\n",
                  100 * p.cpu_share, p.threads, p.threads == 1 ? "thread's" : "threads'");
    return text;
  }
  if (p.load_average < 0 || p.cores <= 0 || p.load_average - p.threads <= 0.5 * p.cores) return "";
  std::snprintf(text, sizeof text,
                "  note: the machine's load average was %.1f on %d cores while the probe ran: "
                "other work shares it, so the run-time figures may read high for a quieter one\n",
                p.load_average, p.cores);
  return text;
}

}  // namespace rockfdem::workflows
