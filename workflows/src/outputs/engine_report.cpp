#include "outputs/engine_report.hpp"

#include <cmath>
#include <cstdio>

#include "rockfdem/error.hpp"

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
  summary.engine =
      EngineFigures{e.phase_times(), e.contact_counters(), e.mass_scaling_report(),
                    long(e.memory_bytes()), double(e.memory_bytes()) / double(e.n_triangles())};
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

double energy_floor(const Scene& scene, const mesh::Mesh& m) {
  const MaterialSpec& rock = scene.materials.at(mesh::kRock);
  const double stress = rock.tensile_strength > 0 ? rock.tensile_strength : 1e-3 * rock.young;
  double area = 0;
  for (const auto& t : m.triangles)
    area += 0.5 * std::abs((m.x[t[1]] - m.x[t[0]]) * (m.y[t[2]] - m.y[t[0]]) -
                           (m.x[t[2]] - m.x[t[0]]) * (m.y[t[1]] - m.y[t[0]]));
  return 1e-6 * stress * stress / (2 * rock.young) * area;
}

void warn_if_unbalanced(const fdem::Engine& e, double floor, bool quiet, RunRecord& summary) {
  const fdem::EnergyBalance b = e.energy_balance();
  if (!(std::abs(b.imbalance()) > kEnergyWarningLimit) || std::abs(b.residual()) <= floor) return;
  char msg[400];
  std::snprintf(msg, sizeof msg,
                "energy: the balance closes only within %.1f%% (sound runs: a few tenths of a "
                "per cent, at most 3%%): extreme parameters or penalties far stiffer than the "
                "rock; treat the results with care (docs/reliability.md)",
                100 * std::abs(b.imbalance()));
  summary.warnings.push_back(msg);
  if (!quiet) std::fprintf(stderr, "rockfdem: warning: %s\n", msg);
}

void check_energy(const fdem::EnergyBalance& b, long step, double floor) {
  const bool sound =
      !(std::abs(b.imbalance()) > kEnergyImbalanceLimit) || std::abs(b.residual()) <= floor;
  if (sound && std::isfinite(b.imbalance())) return;
  char msg[600];
  std::snprintf(msg, sizeof msg,
                "fdem: step %ld: energy balance broken: relative imbalance %.3g (limit %g): "
                "external work %.4g J/m, stored change %.4g, dissipated %.4g, taken out by "
                "stages %.4g: energy was created, so the integration diverged (a dt "
                "forced above the stability limit, or penalties far stiffer than the rock)",
                step, b.imbalance(), kEnergyImbalanceLimit, b.external_work,
                b.stored() - b.initial_stored, b.dissipated(), b.softening + b.removed);
  throw NumericalError(msg);
}

}  // namespace rockfdem::workflows
