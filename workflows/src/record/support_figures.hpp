// The typed parts of a tunnel run's record about its support and damage at
// the end of the run: bolts and cables, the lining ring, the broken zone.
// summary.cpp writes them as summary.json's "bolts", "lining",
// "resolution" and "broken_zone" (docs/output-formats.md).
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "rockfdem/mesh/joints.hpp"

namespace rockfdem::workflows {

/// The peak of an installed bolt's axial force profile.
struct BoltPeak {
  std::string file;  ///< its profile, bolt_NN.csv
  double max_axial_force_kN_per_bar = 0;
  double max_steel_stress_MPa = 0;
  double station_m = 0;  ///< of the peak, from the collar
  bool yielded = false;
  bool broken = false;
  /// The largest tension and the largest compression along the bar [kN per
  /// bar, both >= 0] with their stations, and the tension's steel stress
  /// over the yield and the ultimate strength.
  double max_tension_kN_per_bar = 0, tension_station_m = 0;
  double max_compression_kN_per_bar = 0, compression_station_m = 0;
  double tension_over_yield = 0, tension_over_ultimate = 0;
  std::optional<double> first_broken_station_m;  ///< nearest the collar; none: intact
};

/// One bolt or cable ("bolts"."each"[i]).
struct BoltFigures {
  std::string name;
  std::string kind;  ///< "bolt" or "cable"
  std::array<double, 2> head{}, end{};
  bool installed = false;
  long steel_cracks_yielding = 0, steel_cracks_broken = 0, grout_cracks_broken = 0;
  std::optional<BoltPeak> peak;  ///< none when not installed
};

/// "bolts": the crack element counts over all bolts, and each.
struct BoltRecord {
  long count = 0;
  long steel_cracks_yielding = 0, steel_cracks_broken = 0, grout_cracks_broken = 0;
  std::vector<BoltFigures> each;
};

/// The ring's capacity check (where a compressive strength is given).
struct LiningCapacityFigures {
  std::string section = "plain";  ///< the lining's: "plain", "reinforced" or "steel_sets"
  std::optional<std::string> invert_section;                    ///< the floor part's
  double compressive_strength_Pa = 0, tensile_strength_Pa = 0;  ///< the lining's
  /// The floor part's, with [materials.invert].
  std::optional<double> invert_compressive_strength_Pa, invert_tensile_strength_Pa;
  std::optional<double> min_safety_factor;  ///< none: an unloaded ring
  bool min_safety_factor_in_invert = false;
  double min_safety_factor_angle_deg = 0, min_safety_factor_x_m = 0, min_safety_factor_y_m = 0;
  bool min_safety_factor_at_corner = false;
  long segments_below_1 = 0;
};

/// The extremes at the ring's corner segments (no beam section there).
struct LiningCornerFigures {
  long segments = 0;
  double max_thrust_kN_per_m = 0, max_thrust_angle_deg = 0;
  double min_thrust_kN_per_m = 0, min_thrust_angle_deg = 0;
  double max_abs_moment_kNm_per_m = 0, max_abs_moment_angle_deg = 0;
  /// Their largest thrust, largest |moment| or tension passes the sections'.
  bool exceed_sections = false;
};

/// The lining's section force extremes [kN/m, kNm/m] at the end's step, of
/// the segments that are beam sections (the corners' apart).
struct LiningForceFigures {
  long step = 0;
  long segments = 0, corner_segments = 0;
  double thickness_m = 0;  ///< the median segment's (out of the floor part, with one)
  std::optional<double> invert_thickness_m;  ///< the floor part's median, with [materials.invert]
  double max_thrust_kN_per_m = 0, max_thrust_angle_deg = 0;
  double max_thrust_x_m = 0, max_thrust_y_m = 0;
  bool max_thrust_in_invert = false;
  double min_thrust_kN_per_m = 0, min_thrust_angle_deg = 0;
  double max_abs_moment_kNm_per_m = 0, max_abs_moment_angle_deg = 0;
  double max_abs_shear_kN_per_m = 0, max_abs_shear_angle_deg = 0;
  std::optional<LiningCornerFigures> corners;  ///< with corner segments
  std::string capacity;                        ///< what the check is, or why none
  std::optional<LiningCapacityFigures> check;  ///< with a compressive strength
};

/// "lining": the lining-rock bond and, once the ring is installed, its forces.
struct LiningRecord {
  std::optional<std::pair<long, long>> interface;  ///< bond crack elements, broken
  std::optional<LiningForceFigures> forces;        ///< with lining.csv
  bool empty() const { return !interface && !forces; }
};

/// One point of an extensometer: its head or an anchor.
struct ExtensometerPoint {
  std::string point;  ///< "head", "anchor K"
  double depth_m = 0;
  double relative_mm = 0;  ///< against the deepest anchor
  double absolute_mm = 0;  ///< from the in-situ state
};

/// "extensometers".NAME: a scene's extensometer at the end of the run.
struct ExtensometerFigures {
  std::array<double, 2> head{}, direction{};
  std::optional<std::string> from;  ///< the key point it starts at
  double length_m = 0;
  std::vector<ExtensometerPoint> points;
  std::string read_from = "in-situ state";  ///< or "support" (relative_to_support)
};

/// "outer_boundary": the rigid motion of the model's outer boundary.
struct OuterBoundaryFigures {
  double rotation_deg = 0, max_rotation_deg = 0, limit_deg = 0;
  std::array<double, 2> translation_mm{};
  std::string support;  ///< "rollers" or "tractions"
};

/// "damping": the stages' damping.
struct DampingFigures {
  double local = 0;
  double mass_proportional = 0;  ///< [1/s]
  bool kinetic = false;
  bool local_given = false;  ///< engine.local_damping given by the scene
};

/// "resolution": the fracture zone's element size against l_ch.
struct ResolutionFigures {
  double h_m = 0, l_ch_m = 0, h_over_l_ch = 0, limit = 0;
};

/// One of the rock set's plausibility figures against its range
/// (outputs/rock_plausibility.hpp).
struct PlausibilityFigure {
  std::string name;
  double value = 0, low = 0, high = 0;
  bool in_range = true;
  std::string meaning;  ///< where the range comes from, in words
};

/// "rock_plausibility": the host rock's crack elements' Mohr-Coulomb UCS and
/// the figures an engineer checks a rock set by (UCS / E, ft / UCS, h / l_ch).
struct RockPlausibilityFigures {
  std::string of = "the model's rock";  ///< which set the figures judge
  std::optional<double> ucs_Pa;         ///< none: no cohesion given
  std::vector<PlausibilityFigure> figures;
};

/// The broken depth along one ray from the opening.
struct RayFigures {
  double depth_m = 0;
  /// With a grout stage that re-joined cracks: the depth of the zone broken
  /// at some time, the grouted cracks counted as well as the broken ones.
  std::optional<double> damaged_depth_m;
  std::array<double, 2> origin{}, direction{};
};

/// "broken_zone": how deep the broken crack elements reach.
struct BrokenZoneRecord {
  long broken_rock_cracks = 0;
  double depth_m = 0, fracture_zone_m = 0;
  std::optional<double> clearance_m;  ///< none: no broken crack element
  bool capped = false;
  std::optional<double> ray_half_width_m;  ///< with the rays
  std::map<std::string, RayFigures> rays;  ///< "along_rays"
};

/// Joints at the end of a run: the traces meshed (mesh/joints.hpp) and the
/// state of their crack elements (coupling/joint_cracks.hpp), apart from
/// the intact rock's cracks.
struct JointRecord {
  long set_traces = 0, dfn_traces = 0;  ///< generated by the sets, read from the file
  mesh::JointTraceReport traces;        ///< clipping and slivers
  long elements = 0, active = 0;        ///< joint crack elements, of them between active triangles
  long yielding = 0;                    ///< past the peak (0 < damage < 1)
  long residual = 0;                    ///< sliding on residual friction (damage 1)
};

}  // namespace rockfdem::workflows
