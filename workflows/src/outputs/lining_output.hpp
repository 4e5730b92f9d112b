// What a run writes about its lining ring once installed: lining_NNNNNN.csv
// at each output step, lining.csv at the end, summary "lining" (extremes
// and the smallest safety factor) and the pictures lining_forces.png and
// lining_capacity.png (docs/output-formats.md, docs/support.md).
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "outputs/lining_forces.hpp"
#include "outputs/lining_sections.hpp"
#include "outputs/output_step.hpp"
#include "outputs/run_plots.hpp"
#include "record/support_figures.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

/// The ring's sections: the lining's, and the floor part's where the scene
/// gives [materials.invert].
struct RingSections {
  LiningSection lining;
  std::optional<LiningSection> invert;
};

class LiningOutput : public OutputStepObserver {
 public:
  /// The ring's segments of `m`, those with a mid-line point below
  /// `invert_top` [m] in its floor part (-infinity: none), checked against
  /// `sections` (none: forces only); files go to `dir`.
  LiningOutput(const mesh::Mesh& m, double invert_top, std::optional<RingSections> sections,
               std::string dir);
  /// The ring's segments (as built) and their forces at finish() (empty
  /// before): what support_forces.png draws.
  const LiningGeometry& geometry() const { return geometry_; }
  const std::vector<SectionForces>& final_forces() const { return last_; }
  /// Whether the mesh has a ring to cut into segments.
  bool has_ring() const { return !geometry_.segments.empty(); }
  /// Whether every lining triangle carries load in `e`.
  bool installed(const fdem::Engine& e) const;
  /// Whether the run has installed the ring as lining (before, its
  /// triangles are ground still to be excavated): its forces count from then.
  void set_installed(bool installed) { installed_ = installed; }
  /// The ring's extremes per output step: "lining_max_thrust_kN_per_m",
  /// "lining_max_abs_moment_kNm_per_m", "lining_min_safety_factor".
  std::vector<std::string> history_columns() const override;
  /// DIR/lining_<step>.csv, once installed and every lining triangle is
  /// active, and the ring's extremes (history_values) into the row.
  void at_output_step(const OutputStep& step, std::vector<double>& row) override;
  /// history_columns()' values for forces `f`: the largest thrust [kN/m]
  /// and the largest |moment| [kNm/m] of the segments that are beam
  /// sections (lining_extremes.hpp: the corners' apart), and the smallest
  /// safety factor of all segments, corners too (NaN
  /// without a capacity check or when unloaded); all NaN for no forces
  /// (the ring not installed).
  std::array<double, 3> history_values(const std::vector<SectionForces>& f) const;
  /// DIR/lining.csv and the ring's force extremes and capacity check; given
  /// `plots`, lining_forces.png and (with a compressive strength)
  /// lining_capacity.png.
  LiningForceFigures finish(const fdem::Engine& e, const std::string& dir, PlotWriter* plots);

 private:
  /// DIR/lining.csv and the figures of finish().
  LiningForceFigures figures(const fdem::Engine& e, const std::string& dir);
  /// The pictures of finish(), of the state figures() saw.
  void plots(PlotWriter& plots) const;
  /// lining_capacity.png, of the segments' M and N [kNm/m, kN/m].
  void capacity_plot(PlotWriter& plots, const std::vector<double>& m,
                     const std::vector<double>& n) const;
  std::vector<SectionForces> forces(const fdem::Engine& e) const;
  /// Each segment's safety factor for `f` (with sections_).
  std::vector<double> safety_factors(const std::vector<SectionForces>& f) const;
  /// lining.csv's text for `f` at `step`.
  std::string csv(long step, const std::vector<SectionForces>& f) const;
  /// The figures of the safety factor check into `f`.
  void check_capacity(LiningForceFigures& f) const;
  LiningGeometry geometry_;
  std::vector<int> triangles_;  ///< every lining triangle
  /// Segment i's section (with sections_): its part's.
  const LiningSection& section_of(std::size_t i) const;
  std::optional<RingSections> sections_;
  std::vector<char> segment_invert_;  ///< per segment: in the floor part
  std::vector<SectionForces> last_;   ///< forces of finish()
  std::string dir_;
  bool installed_ = false;
};

/// The sections the scene gives (materials.lining, materials.invert);
/// none without the lining's compressive strength.
std::optional<RingSections> ring_sections(const Scene& scene);

/// The bond's crack elements between two active triangles and how many
/// broke; none when no bond acts (a ring never installed, or removed).
std::optional<std::pair<long, long>> lining_bond(const fdem::Engine& e, const mesh::Mesh& m);

}  // namespace rockfdem::workflows
