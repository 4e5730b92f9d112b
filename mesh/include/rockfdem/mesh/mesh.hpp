// The plain in-memory mesh every stage shares: vertices, counter-clockwise
// triangles with a zone per triangle, and tagged edges. No gmsh types here:
// deal.II (insitu/), the explicit engine (via coupling/) and the writers all
// read this record.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace rockfdem::mesh {

/// Zone of a triangle (the deal.II material id and the engine's material).
enum Zone : int {
  kRock = 1,    ///< host rock (or the whole specimen)
  kCore = 2,    ///< excavation core inside the tunnel opening
  kLining = 3,  ///< shotcrete lining ring just inside the tunnel boundary
};

/// Tag of an edge (the deal.II boundary id). Outer boundary edges have
/// exactly one triangle; interface edges (excavation, lining inner face)
/// have two.
enum EdgeTag : int {
  kBottom = 1,       ///< outer boundary y = ymin (UCS: lower platen)
  kRight = 2,        ///< outer boundary x = xmax
  kTop = 3,          ///< outer boundary y = ymax (UCS: upper platen)
  kLeft = 4,         ///< outer boundary x = xmin
  kExcavation = 5,   ///< tunnel boundary: rock (outside) against lining/core
  kLiningInner = 6,  ///< lining ring against core
  kRim = 7,          ///< Brazilian disc rim outside the loading arcs
  kLoadTop = 8,      ///< Brazilian disc upper loading arc
  kLoadBottom = 9,   ///< Brazilian disc lower loading arc
};

struct TaggedEdge {
  int a = 0;    ///< first vertex
  int b = 0;    ///< second vertex
  int tag = 0;  ///< an EdgeTag (or a user tag >= 100 from a .msh file)
};

/// A mesh edge on a joint trace: vertices a, b and the index of the trace
/// (in the prepared traces, joints.hpp) it lies on.
struct JointEdge {
  int a = 0;
  int b = 0;
  int trace = 0;
};

struct Mesh {
  std::vector<double> x, y;                   ///< vertex coordinates [m]
  std::vector<std::array<int, 3>> triangles;  ///< counter-clockwise vertex ids
  std::vector<int> zone;                      ///< per triangle: a Zone
  std::vector<std::uint8_t> fracture;         ///< per triangle: 1 where crack elements are allowed
  std::vector<TaggedEdge> edges;              ///< tagged boundary and interface edges
  std::vector<JointEdge> joint_edges;         ///< edges on joint traces

  std::size_t n_vertices() const { return x.size(); }
  std::size_t n_triangles() const { return triangles.size(); }
};

/// Quality figures reported after meshing.
struct MeshQuality {
  double min_altitude = 0;   ///< smallest triangle altitude [m] (sets the stable time step)
  double min_angle_deg = 0;  ///< smallest interior angle [deg]
  double total_area = 0;     ///< sum of triangle areas [m^2]
};

MeshQuality measure_quality(const Mesh& m);

/// Signed area of triangle t (positive when counter-clockwise).
double signed_area(const Mesh& m, std::size_t t);

}  // namespace rockfdem::mesh
