// Private: the checks an engineer makes of a scene's inputs before a run:
// bolts placed from the opening into the rock, stresses or moduli whose
// size says they were given in the wrong unit, and quasi-static stages
// left without any damping.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "rockfdem/mesh/mesh_spec.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "scene/scene_reader.hpp"

namespace rockfdem::workflows::detail {

/// One bolt or cable as the scene gives it.
struct BoltPlacement {
  std::string
      collar_key;       ///< the key that places the collar ("bolt[2].start", "bolt_fan[0].centre")
  std::string end_key;  ///< the key that places the end ("bolt[2].end", "bolt_fan[0].length")
  std::string label;    ///< which bolt ("bolt[2]", "bolt 3 of 9 of bolt_fan[0] (52.5 deg)")
  std::array<double, 4> seg;  ///< collar (x0, y0), end (x1, y1) [m]
};

/// Refuses (InputError via fail_key) a bolt of zero length, one reaching
/// outside the domain and, in a generated tunnel, one running through the
/// opening or whose collar (start) lies neither on the excavation boundary
/// nor in the lining, within max(mesh.size_near / 2, 5 cm).
void check_bolt_placement(const RawScene& raw, const mesh::MeshSpec& m, const BoltPlacement& b);

/// The collar tolerance of check_bolt_placement [m].
double collar_tolerance(const mesh::MeshSpec& m);

/// Warnings for in-situ stresses below 10 kPa and moduli (Young's, tangent)
/// below 1 MPa given in the scene: probably MPa written as Pa.
std::vector<std::string> unit_warnings(const RawScene& raw);

/// A warning when the tunnel stages, quasi-static runs to equilibrium, get
/// no damping at all: engine.local_damping = 0, no kinetic or mass
/// damping, engine.damping_ratio = 0 and no contact damping. Their
/// vibration then never decays, and blocks held by friction ratchet on it
/// (docs/engine.md, "Sticking and undamped ratcheting").
std::vector<std::string> damping_warnings(const RawScene& raw, const Scene& s);

}  // namespace rockfdem::workflows::detail
