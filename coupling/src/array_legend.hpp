// What the arrays of a rockfdem .vtu mean: units, sign convention and the
// codes of the integer arrays, written into each file as field data so the
// file explains itself in ParaView (docs/output-formats.md says the same).
#pragma once

#include "rockfdem/coupling/vtk_grid.hpp"

namespace rockfdem::coupling {

inline void add_array_legend(VtkFieldData& f, bool joints = false) {
  static const char* const kLegend[][2] = {
      {"units",
       "coordinates, displacement: m; velocity: m/s; stress, principal_stress, "
       "bolt_axial_stress: Pa; damage: 1 (0 intact to 1 broken)"},
      {"stress_sign_convention",
       "tension positive: compression is negative (the scene gives in-situ stresses "
       "compression positive)"},
      {"stress_components", "xx, yy, zz, xy; zz is the out-of-plane stress of plane strain"},
      {"principal_stress_components",
       "in-plane s1 >= s2: s1 the most tensile (least compressive), s2 the most compressive"},
      {"zone_codes", "1 rock (or specimen), 2 excavation core, 3 lining; user meshes: their zones"},
      {"active_codes", "1 in the model, 0 removed (excavated) or not yet installed"},
      {"crack_state_codes", "crack elements: 0 intact, 1 yielding, 2 broken; -1 on triangles"},
      {"failure_mode_codes",
       "crack elements: 0 none, 1 mode I, 2 mode II, 3 mixed; -1 on triangles"}};
  for (const auto& entry : kLegend) f.text.push_back({entry[0], entry[1]});
  if (joints)
    f.text.push_back({"joint_codes",
                      "crack elements: 0 intact rock, k > 0 on joint trace k (1-based, in the "
                      "order of joints.csv); -1 on triangles"});
}

}  // namespace rockfdem::coupling
