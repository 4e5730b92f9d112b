#include "stages/platen_load.hpp"

#include <algorithm>
#include <cmath>

#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::workflows {

PlatenLoad::PlatenLoad(const Scene& s)
    : disc_(s.mesh.kind == mesh::ModelKind::kBrazilian),
      upper_tag_(disc_ ? mesh::kLoadTop : mesh::kTop),
      length_(disc_ ? s.mesh.specimen.diameter : s.mesh.specimen.height),
      section_(disc_ ? 1.0 : s.mesh.specimen.width),
      velocity_(s.engine.platen_velocity),
      stop_fraction_(s.engine.stop_after_peak) {}

PlatenReading PlatenLoad::read(const fdem::Engine& e) const {
  PlatenReading r;
  r.force = -e.boundary_force(upper_tag_)[1];
  // UCS: mean axial stress; disc: the Brazilian tensile stress 2P/(pi D t).
  r.stress = disc_ ? 2 * r.force / (M_PI * length_) : r.force / section_;
  r.strain = 2 * velocity_ * e.time() / length_;
  return r;
}

bool PlatenLoad::after_step(const fdem::Engine& e) {
  if (stopped_) return true;
  const PlatenReading r = read(e);
  if (!disc_) curve_.add(r.strain, r.stress);
  if (r.stress > peak_.stress) {
    peak_ = r;
    peak_step_ = e.step_count();
  }
  // Broken crack elements are counted only when the stress is low enough:
  // before the first break (the loading wave's first steps) the stress may
  // dip below the fraction without any fracture.
  if (stop_fraction_ > 0 && peak_.stress > 0 && r.stress <= stop_fraction_ * peak_.stress &&
      e.broken_counts().total() > 0) {
    stopped_ = true;
    stop_step_ = e.step_count();
  }
  return stopped_;
}

nlohmann::json PlatenLoad::state() const {
  nlohmann::json s = {{"peak_stress", peak_.stress}, {"peak_strain", peak_.strain},
                      {"peak_force", peak_.force},   {"peak_step", peak_step_},
                      {"stopped", stopped_},         {"stop_step", stop_step_}};
  if (!disc_) s["curve"] = curve_.state();
  return s;
}

void PlatenLoad::restore(const nlohmann::json& s) {
  peak_.stress = s.at("peak_stress").get<double>();
  peak_.strain = s.at("peak_strain").get<double>();
  peak_.force = s.value("peak_force", 0.0);
  peak_step_ = s.at("peak_step").get<long>();
  stopped_ = s.at("stopped").get<bool>();
  stop_step_ = s.value("stop_step", 0L);
  // A checkpoint written before the curve was kept restores without it:
  // the modulus is then read from the steps after the restart alone.
  if (!disc_ && s.contains("curve")) curve_.restore(s.at("curve"));
}

SpecimenRecord PlatenLoad::record() const {
  SpecimenRecord r;
  r.kind = disc_ ? "brazilian" : "ucs";
  r.peak_stress = peak_.stress;
  r.peak_force = peak_.force;
  r.peak_step = peak_step_;
  r.peak_strain = peak_.strain;
  r.strain_rate = 2 * velocity_ / length_;
  r.stop_after_peak = stop_fraction_;
  if (!disc_) r.modulus = curve_.modulus(peak_.stress, peak_.strain);
  if (stopped_) r.stopped_after_peak_at_step = stop_step_;
  return r;
}

}  // namespace rockfdem::workflows
