// The load a specimen carries, read from the upper platen's reaction: the
// history's stress and strain columns and, after every step, the peak (with
// its step and strain) and the post-peak stop. The reaction is a
// fixed-order sum over the platen's nodes (Engine::boundary_force), so the
// peak is the same for any thread count and costs no allocation.
#pragma once

#include <nlohmann/json.hpp>

#include "record/run_figures.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "stages/prepeak_curve.hpp"

namespace rockfdem::workflows {

struct PlatenReading {
  double force = 0;   ///< upper platen's reaction per unit thickness [N/m], compression positive
  double stress = 0;  ///< UCS: force / width; disc: 2 force / (pi D) [Pa]
  double strain = 0;  ///< nominal axial strain 2 v t / L (L: height or diameter) [-]
};

class PlatenLoad {
 public:
  explicit PlatenLoad(const Scene& scene);
  PlatenReading read(const fdem::Engine& e) const;
  /// After each step: keeps the peak; true once the post-peak stop holds
  /// (stress at most loading.stop_after_peak times the peak, with a crack
  /// element broken), and from then on.
  bool after_step(const fdem::Engine& e);
  bool stopped() const { return stopped_; }
  /// The state a checkpoint keeps, and its restoration.
  nlohmann::json state() const;
  void restore(const nlohmann::json& s);
  /// The peak and the post-peak stop so far (summary.json's "specimen").
  SpecimenRecord record() const;

 private:
  bool disc_;
  int upper_tag_;
  double length_, section_, velocity_, stop_fraction_;
  PlatenReading peak_;
  long peak_step_ = 0;
  bool stopped_ = false;
  long stop_step_ = 0;
  PrePeakCurve curve_;  ///< UCS: for the pre-peak modulus
};

}  // namespace rockfdem::workflows
