#include "commands/check_probe.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>

#include "commands/commands.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/build.hpp"
#include "stages/platen_load.hpp"
#include "stages/stage_inputs.hpp"

namespace rockfdem::workflows {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
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

// Enough steps to time (about 3 M triangle-steps), a few hundred at most.
long probe_steps(std::size_t triangles) {
  return std::clamp<long>(long(3e6 / double(std::max<std::size_t>(triangles, 1))), 20, 300);
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
  const Clock::time_point t1 = Clock::now();
  for (long k = 0; k < p.steps; ++k) engine.step();
  p.seconds_per_step = seconds_since(t1) / double(p.steps);

  engine.set_mass_scaling({false, 0.0});
  engine.set_damping(start_damping);
  p.critical_true = engine.critical_dt();
  return p;
}

}  // namespace rockfdem::workflows
