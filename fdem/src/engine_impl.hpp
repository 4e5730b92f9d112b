// What the public Engine holds behind its pointer. Shared by engine.cpp
// (construction, stepping, stage controls) and diagnostics.cpp (global
// figures).
#pragma once

#include "engine_data.hpp"
#include "rockfdem/fdem/engine.hpp"

namespace rockfdem::fdem {

struct Engine::Impl {
  detail::EngineData d;
  PhaseTimes times;
  double dt_safety = 0.8;
  double critical_dt = -1;         ///< cached; < 0 when it must be recomputed
  bool auto_dt = true;             ///< dt follows dt_safety * critical_dt
  bool forced_dt = false;          ///< an explicit dt above the limit was forced
  int reversals = 0;               ///< consecutive steps with growing velocity reversal
  bool prestress_pending = false;  ///< crack pre-stress is set before the first step
  long prestress_clipped = 0;      ///< crack points whose initial traction exceeded the strength
  void refresh();
  /// A stiffness, damping or contact change: the stability limit is
  /// recomputed, and with mass scaling the density factors follow.
  void stiffness_changed() {
    critical_dt = -1;
    // Scaled masses follow the stiffness, and so does the weight of a
    // softened triangle (node_update.cpp, weight_mass).
    const bool gravity = d.gravity[0] != 0.0 || d.gravity[1] != 0.0;
    if (d.mass_scaling.enabled || gravity) d.masses_dirty = true;
  }
};

}  // namespace rockfdem::fdem
