// Monitor points on the tunnel boundary: vault (crown), shoulders,
// sidewalls and invert. They are placed on the excavation boundary found in
// the mesh itself (rockfdem/mesh/opening.hpp: the rock's inner boundary,
// against core, lining or nothing), by the rules of the tunnel's shape, or
// from the opening's centroid for a user's mesh; each is tied to the engine
// node of a rock triangle at the boundary vertex nearest to its point.
// Displacements include the implicit stage's excavation-induced part (they
// are measured from the in-situ state).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "outputs/material_point.hpp"
#include "outputs/outer_boundary.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/mesh/mesh_spec.hpp"

namespace rockfdem::workflows {

/// What a key point is on the opening: the run's checks and chords find
/// points by role, the outputs name them (Monitor::name).
enum class KeyRole { kVault, kLeftShoulder, kRightShoulder, kLeftWall, kRightWall, kInvert };

struct Monitor {
  std::string name;  ///< vault, left_shoulder, right_shoulder, left_wall, right_wall, invert
  KeyRole role = KeyRole::kVault;
  double x = 0, y = 0;                ///< key point on the mesh's excavation boundary [m]
  int node = -1;                      ///< engine node followed
  double node_x = 0, node_y = 0;      ///< where that node is: the actual monitor position [m]
  double inward_x = 0, inward_y = 0;  ///< unit vector towards the opening's centre: u . inward
                                      ///< is the radial convergence (> 0 into the opening)
};

/// The standard monitor points, tied to engine nodes. A generated tunnel
/// (spec.kind kTunnel) uses the rules of spec.tunnel's shape; a user's mesh
/// (kMshFile) the shape-free rules (docs/meshing.md, "Key points").
/// Throws rockfdem::InputError naming spec.msh.path when the mesh has no
/// excavation boundary (no rock triangle edge faces core, lining or a hole).
std::vector<Monitor> tunnel_monitors(const mesh::MeshSpec& spec, const mesh::Mesh& m,
                                     const fdem::Engine& e);

/// A key point as the mesh alone places it: its nearest vertex of the
/// opening (the vertex of tunnel_monitors' node) and its inward normal.
struct KeyPointVertex {
  int vertex = -1;
  double inward_x = 0, inward_y = 0;
};

/// tunnel_monitors' key points, in its order, before there is an engine;
/// none when the mesh has no opening (tunnel_monitors then refuses it).
std::vector<KeyPointVertex> key_point_vertices(const mesh::MeshSpec& spec, const mesh::Mesh& m);

/// Radial convergence of a displacement at a monitor: u . inward [m].
double radial_convergence(const Monitor& mon, const std::array<double, 2>& u);

/// Displacement of an engine node from the in-situ state: the implicit
/// stage's part at its mesh vertex (may be empty) plus the engine's [m].
std::array<double, 2> node_displacement(const fdem::Engine& e, int node,
                                        const std::vector<double>& implicit_ux,
                                        const std::vector<double>& implicit_uy);

/// Displacement of a monitor from the in-situ state: the implicit stage's
/// part (per mesh vertex, may be empty) plus the engine's increment [m].
std::array<double, 2> monitor_displacement(const fdem::Engine& e, const Monitor& mon,
                                           const std::vector<double>& implicit_ux,
                                           const std::vector<double>& implicit_uy);

/// A tunnel run's key points as its outputs read them: displacements from
/// the in-situ state (the implicit stage's part plus the engine's) with the
/// outer boundary's mean translation removed, and the closure of chords
/// between points.
class KeyPoints {
 public:
  KeyPoints() = default;
  /// `m`'s outer boundary defines the rigid translation removed;
  /// `implicit_ux`, `implicit_uy` are the hand-off field's per mesh vertex
  /// (empty: none).
  KeyPoints(std::vector<Monitor> monitors, const mesh::Mesh& m, std::vector<double> implicit_ux,
            std::vector<double> implicit_uy);
  const std::vector<Monitor>& monitors() const { return monitors_; }
  /// The key point of `role`.
  const Monitor& find(KeyRole role) const;
  /// The opening's span as its wall key points measure it [m]; 0 without
  /// key points (a specimen).
  double span() const;
  /// Rigid motion of the outer boundary in the engine (fit to its nodes).
  RigidFit boundary_fit(const fdem::Engine& e) const;
  /// Any engine node's displacement, as the instruments read it.
  NodeDisplacement node_displacements(const fdem::Engine& e) const;
  /// A key point's displacement [m].
  std::array<double, 2> displacement(const fdem::Engine& e, const Monitor& mon) const;
  /// One key point's figures [mm]: ux, uy, |u| and the component towards
  /// the opening (convergence positive).
  std::array<double, 4> figures(const fdem::Engine& e, const Monitor& mon) const;
  /// The vault's settlement, the walls' and the shoulders' chord
  /// convergence (closure along the chord, positive inwards) [mm].
  std::array<double, 3> chords_mm(const fdem::Engine& e) const;
  /// The key point of `monitors` displaced most and |u| [m].
  std::pair<std::string, double> largest(const fdem::Engine& e,
                                         const std::vector<Monitor>& monitors) const;

 private:
  double convergence(const fdem::Engine& e, KeyRole a, KeyRole b) const;
  std::vector<Monitor> monitors_;
  std::vector<double> implicit_ux_, implicit_uy_;
  std::vector<int> boundary_vertices_;  ///< outer boundary, for the rigid translation
  mutable long fit_step_ = -1;          ///< step the cached fit belongs to
  mutable RigidFit fit_;
};

}  // namespace rockfdem::workflows
