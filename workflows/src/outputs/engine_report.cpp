#include "outputs/engine_report.hpp"

namespace rockfdem::workflows {

EngineState engine_state(const fdem::Engine& e, const fdem::EnergyBalance& en) {
  return {e.step_count(), e.dt(), e.time(), e.broken_counts(), en, e.state_hash()};
}

namespace {

// What the run skipped of the engine's modules, and why.
void note_skipped(const fdem::Engine& e, RunRecord& summary) {
  const fdem::ContactCounters c = e.contact_counters();
  if (!c.enabled)
    summary.skipped.push_back("contact: disabled by the scene (contact.enabled = false)");
  else if (c.steps_with_pairs == 0)
    summary.skipped.push_back("contact: nothing could touch in " + std::to_string(e.step_count()) +
                              " steps");
  else if (c.steps_skipped > 0)
    summary.skipped.push_back("contact: nothing could touch in " + std::to_string(c.steps_skipped) +
                              " of " + std::to_string(e.step_count()) + " steps");
  if (e.n_cracks() == 0) summary.skipped.push_back("crack elements: fracture is allowed nowhere");
  if (!e.mass_scaling_report().enabled)
    summary.skipped.push_back("mass scaling: off (engine.mass_scaling); dynamics at true masses");
}

}  // namespace

void report_engine(const fdem::Engine& e, const PhaseTimer& timer, RunRecord& summary) {
  summary.counts.triangles = long(e.n_triangles());
  summary.counts.nodes = long(e.n_nodes());
  summary.counts.crack_elements = long(e.n_cracks());
  summary.state = engine_state(e, e.energy_balance());
  // One dt throughout, unless a staged run widens the range (RunOutputs).
  summary.dt_range = std::make_pair(e.dt(), e.dt());
  const double fdem = timer.seconds("fdem");
  summary.triangle_steps_per_second =
      fdem > 0 ? double(e.n_triangles()) * double(e.step_count()) / fdem : 0.0;
  summary.engine = EngineFigures{e.phase_times(),
                                 e.contact_counters(),
                                 e.mass_scaling_report(),
                                 long(e.memory_bytes()),
                                 double(e.memory_bytes()) / double(e.n_triangles()),
                                 e.memory_breakdown()};
  note_skipped(e, summary);
}

std::vector<std::string> energy_columns() {
  return {"external_work",     "stored_change",   "dissipated",
          "removed_by_stages", "energy_residual", "energy_imbalance"};
}

std::vector<double> energy_row(const fdem::EnergyBalance& b) {
  return {b.external_work, b.stored() - b.initial_stored,
          b.dissipated(),  b.softening + b.removed,
          b.residual(),    b.imbalance()};
}

}  // namespace rockfdem::workflows
