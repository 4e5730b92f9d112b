// Readings a tunnel run takes besides its key points (monitors.hpp): the
// scene's [[monitor]] points and [[extensometer]] lines, each point a
// material point of the rock (material_point.hpp), and the depth of the
// broken zone along each key point's outward normal (broken_zone.hpp).
//
// Extensometer convention (a borehole extensometer's): points k = 0 (the
// head) .. n (the deepest anchor) at depth k L / n along the unit axis e
// from the head into the rock; the absolute reading of point k is its
// displacement towards the opening along the axis, -u_k . e, and the
// relative reading (u_n - u_k) . e, the motion of point k towards the head
// relative to the deepest anchor, taken as fixed: positive when the rock
// between them stretches (converging ground).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "outputs/broken_zone.hpp"
#include "outputs/material_point.hpp"
#include "outputs/monitors.hpp"
#include "outputs/output_step.hpp"
#include "record/summary.hpp"
#include "rockfdem/fdem/bolt_install.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

class Instruments : public OutputStepObserver {
 public:
  /// Places every monitor and extensometer point in the mesh. Throws
  /// rockfdem::InputError naming the scene, the key (monitor[i],
  /// extensometer[i]), the name and the point's coordinates when no
  /// triangle holds it or the triangle is the excavated core's.
  Instruments(const Scene& scene, const mesh::Mesh& m, const fdem::Engine& e,
              const std::vector<Monitor>& key_points, const fdem::BoltPlan& bolts);

  /// history.csv's columns: per monitor <name>_ux_mm, _uy_mm, _u_mm; per
  /// extensometer <name>_a<k>_mm (relative, k = 0 .. n - 1) and
  /// <name>_a<k>_abs_mm (k = 0 .. n); per key point <name>_broken_depth_m.
  std::vector<std::string> history_columns() const override;
  /// The values of history_columns() for a history row.
  std::vector<double> row(const fdem::Engine& e, const mesh::Mesh& m,
                          const NodeDisplacement& u) const;
  void at_output_step(const OutputStep& s, std::vector<double>& r) override {
    for (double v : row(s.engine, s.mesh, s.u)) r.push_back(v);
  }
  /// A `lining` or `bolts` stage has just installed its support: the first
  /// call fixes the zero of the monitors read relative to the support.
  void support_installed(const NodeDisplacement& u);
  /// Adds each of the scene's monitors (ux, uy, |u| [mm], point and
  /// convention) to the record's monitors.
  void add_monitors(MonitorRecord& monitors, const NodeDisplacement& u) const;
  /// summary.json's "extensometers" and "broken_zone"."along_rays".
  void finish(RunRecord& summary, const fdem::Engine& e, const mesh::Mesh& m,
              const NodeDisplacement& u) const;
  /// A grout stage re-joined these crack elements: from now on the rays
  /// also read the depth of the zone broken at some time, grouted since.
  void cracks_grouted(const std::vector<StageChanges::Grouted>& grouted, std::size_t n_cracks);
  /// The support reference and the grouted cracks, for a restart.
  nlohmann::json state() const;
  void restore(const nlohmann::json& state);

 private:
  struct Extensometer {
    const ExtensometerSpec* spec;
    double x = 0, y = 0, dx = 0, dy = 0;  ///< head and unit axis into the rock
    std::vector<MaterialPoint> points;    ///< head, then anchors 1 .. n
  };
  /// u of monitor i [m], relative to the support where it asks.
  std::array<double, 2> monitor_u(std::size_t i, const NodeDisplacement& u) const;
  /// Per point of x: absolute reading [m] (towards the opening along the axis).
  std::vector<double> axial(const Extensometer& x, const NodeDisplacement& u) const;
  /// axial() less its value at the support where x asks (0 before).
  std::vector<double> reading(std::size_t i, const NodeDisplacement& u) const;
  std::vector<MonitorSpec> specs_;       ///< the scene's monitors, as it gave them
  std::vector<MaterialPoint> monitors_;  ///< per scene monitor
  std::vector<Extensometer> extensometers_;
  std::vector<std::string> ray_names_;  ///< key points
  std::vector<Ray> rays_;
  double half_width_ = 0;              ///< half the fracture zone's element size [m]
  std::vector<char> bolted_;           ///< bolt triangles, left out of the broken zone
  std::vector<char> grouted_;          ///< per crack element, once a grout stage fired
  bool installed_ = false;             ///< whether the first support stage has begun
  std::vector<double> support_u_;      ///< (ux, uy) per monitor at the support
  std::vector<double> support_axial_;  ///< axial() per extensometer point at the support
};

}  // namespace rockfdem::workflows
