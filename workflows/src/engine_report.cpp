#include "engine_report.hpp"

namespace rockfdem::workflows {

void report_engine(const fdem::Engine& e, const PhaseTimer& timer, RunSummary& summary) {
  auto& j = summary.json();
  j["counts"]["triangles"] = e.n_triangles();
  j["counts"]["nodes"] = e.n_nodes();
  j["counts"]["crack_elements"] = e.n_cracks();
  j["steps"] = e.step_count();
  j["dt"] = e.dt();
  j["simulated_time"] = e.time();
  const double fdem = timer.seconds("fdem");
  j["throughput"]["triangle_steps_per_second"] =
      fdem > 0 ? double(e.n_triangles()) * double(e.step_count()) / fdem : 0.0;
  const fdem::BrokenCounts b = e.broken_counts();
  j["broken"] = {{"mode_I", b.mode_I}, {"mode_II", b.mode_II}, {"mixed", b.mixed}};
  const fdem::PhaseTimes p = e.phase_times();
  j["fdem_modules"] = {{"triangles", p.triangles}, {"cracks", p.cracks}, {"nodes", p.nodes},
                       {"contact", p.contact}};
  const fdem::ContactCounters c = e.contact_counters();
  j["contact"] = {{"enabled", c.enabled},          {"detections", c.detections},
                  {"steps_with_pairs", c.steps_with_pairs}, {"steps_skipped", c.steps_skipped},
                  {"last_candidates", c.candidates}, {"last_pairs", c.pairs},
                  {"last_touching", c.touching}};
  if (!c.enabled)
    summary.skipped("contact: disabled by the scene (contact.enabled = false)");
  else if (c.steps_with_pairs == 0)
    summary.skipped("contact: nothing could touch in " + std::to_string(e.step_count()) +
                    " steps");
  else if (c.steps_skipped > 0)
    summary.skipped("contact: nothing could touch in " + std::to_string(c.steps_skipped) +
                    " of " + std::to_string(e.step_count()) + " steps");
  if (e.n_cracks() == 0) summary.skipped("crack elements: fracture is allowed nowhere");
  j["memory_bytes"] = e.memory_bytes();
  j["memory_bytes_per_triangle"] = double(e.memory_bytes()) / double(e.n_triangles());
  j["state_hash"] = e.state_hash();
}

}  // namespace rockfdem::workflows
