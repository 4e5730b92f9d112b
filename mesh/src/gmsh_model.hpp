// Private to mesh/: the steps between a MeshSpec and a Mesh inside one open
// gmsh session. A builder adds and synchronizes an OCC model and says which
// surface is which zone and which curve carries which edge tag; the size
// functions set how fine to mesh; extraction turns gmsh's mesh into the
// plain record. No gmsh types appear here, only gmsh entity tags.
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/mesh/mesh_spec.hpp"
#include "rockfdem/mesh/outline.hpp"

namespace rockfdem::mesh::detail {

struct GmshModelMap {
  std::vector<std::pair<int, int>> surface_zone;  ///< (gmsh surface tag, Zone)
  std::vector<std::pair<int, int>> curve_tag;     ///< (gmsh curve tag, EdgeTag)
  std::vector<std::pair<int, int>> joint_curve;   ///< (gmsh curve tag, joint trace index)
};

// --- geometry (tunnel_geometry.cpp, specimen_geometry.cpp) ---------------

/// The tunnel in its rock rectangle, with `joints` (prepared: in the rock)
/// as embedded curves. Throws InputError when it does not fit.
GmshModelMap add_tunnel_model(const MeshSpec& spec, const std::vector<JointTrace>& joints = {});
/// UCS specimen: x in [-w/2, w/2], y in [0, h] (the lower platen at y = 0).
GmshModelMap add_ucs_model(const SpecimenSpec& s);
/// Brazilian disc of the given diameter centred on the origin.
GmshModelMap add_disc_model(const SpecimenSpec& s);

/// Adds a plane OCC surface bounded by `o` (not synchronized); returns its tag.
/// Arcs are split into pieces of at most 90 degrees: OCC's three-point arc is
/// undefined for a half circle.
int add_outline_surface(const Outline& o);
/// Tag of every curve on the boundary of surface `s` (model synchronized).
std::vector<int> boundary_curves(int s);
/// Edge tag of an outer-rectangle curve from where its bounding box lies.
int rectangle_side_tag(int curve, double xmin, double ymin, double xmax, double ymax);

// --- mesh size (size_field.cpp) -------------------------------------------

/// Size `h` everywhere (specimens).
void set_uniform_size(double h, int algorithm);
/// Distance + Threshold grading from the excavation curves, near size in the
/// fracture zone, core and lining (see docs/meshing.md).
void set_tunnel_size_field(const MeshSpec& spec, const GmshModelMap& model);
/// The grading distance actually used (spec value, or the automatic one).
double grading_distance(const MeshSpec& spec);

// --- extraction (gmsh_extract.cpp) ----------------------------------------

/// gmsh node tag -> index into the node arrays (dense or hashed).
class TagIndex {
 public:
  explicit TagIndex(const std::vector<std::size_t>& tags);
  int operator()(std::size_t tag) const;  ///< -1 when unknown
  std::size_t n_duplicates() const { return n_duplicates_; }
  std::size_t first_duplicate() const { return first_duplicate_; }

 private:
  std::vector<int> dense_;
  std::unordered_map<std::size_t, int> sparse_;
  std::size_t n_duplicates_ = 0, first_duplicate_ = 0;
};

/// All nodes of the current gmsh model into m.x, m.y (and their z into
/// `z` where given); returns their tags.
std::vector<std::size_t> read_gmsh_nodes(Mesh& m, std::vector<double>* z = nullptr);
/// Appends the 3-node triangles of surface `s` (indices into m.x) with zone
/// and fracture flag; returns their gmsh element tags. Throws
/// std::runtime_error naming the type when `s` holds other 2D elements.
std::vector<std::size_t> append_triangles(int s, int zone, std::uint8_t fracture,
                                          const TagIndex& index, Mesh& m);
/// Appends the 2-node lines of curve `c` as tagged edges.
void append_edges(int c, int tag, const TagIndex& index, Mesh& m);
/// Drops vertices no triangle uses and renumbers the rest in order.
void compact_vertices(Mesh& m);
/// Turns clockwise triangles counter-clockwise.
void orient_counter_clockwise(Mesh& m);
/// Whole extraction for a generated model.
Mesh extract_mesh(const GmshModelMap& model);

}  // namespace rockfdem::mesh::detail
