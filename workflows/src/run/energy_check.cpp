#include "run/energy_check.hpp"

#include <cmath>
#include <cstdio>

#include "rockfdem/error.hpp"

namespace rockfdem::workflows {
namespace {

double model_area(const mesh::Mesh& m) {
  double area = 0;
  for (const auto& t : m.triangles)
    area += 0.5 * std::abs((m.x[t[1]] - m.x[t[0]]) * (m.y[t[2]] - m.y[t[0]]) -
                           (m.x[t[2]] - m.x[t[0]]) * (m.y[t[1]] - m.y[t[0]]));
  return area;
}

}  // namespace

EnergyCheck::EnergyCheck(const Scene& scene, const mesh::Mesh& m) {
  const MaterialSpec& rock = scene.materials.at(mesh::kRock);
  const double stress = rock.tensile_strength > 0 ? rock.tensile_strength : 1e-3 * rock.young;
  floor_ = 1e-6 * stress * stress / (2 * rock.young) * model_area(m);
}

void EnergyCheck::at_output_step(const fdem::EnergyBalance& b, long step) const {
  const bool sound =
      !(std::abs(b.imbalance()) > kEnergyImbalanceLimit) || std::abs(b.residual()) <= floor_;
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

void EnergyCheck::warn_if_unbalanced(const fdem::Engine& e, bool quiet, RunRecord& summary) const {
  const fdem::EnergyBalance b = e.energy_balance();
  if (!(std::abs(b.imbalance()) > kEnergyWarningLimit) || std::abs(b.residual()) <= floor_) return;
  char msg[400];
  std::snprintf(msg, sizeof msg,
                "energy: the balance closes only within %.1f%% (sound runs: a few tenths of a "
                "per cent, at most 3%%): extreme parameters or penalties far stiffer than the "
                "rock; treat the results with care (docs/reliability.md)",
                100 * std::abs(b.imbalance()));
  summary.warnings.push_back(msg);
  if (!quiet) std::fprintf(stderr, "rockfdem: warning: %s\n", msg);
}

}  // namespace rockfdem::workflows
