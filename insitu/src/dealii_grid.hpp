// What the elastic and the Mohr-Coulomb in-situ problems share, with deal.II
// types: the triangulation built from the mesh record, the load kind of each
// boundary face, the in-situ stress, the rigid-motion constraints and their
// removal from the reported displacement, the direct solver. Defined in
// insitu_problem.cpp (deal.II stays in as few translation units as it can).
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <cstdint>
#include <string>
#include <unordered_set>
#include <vector>

#include "rockfdem/insitu/insitu.hpp"

namespace rockfdem::insitu::grid {

/// The load kind of a boundary face, kept in its user index:
///   kLoaded: an edge on the outer boundary of the FULL mesh (one triangle
///            there): it carries the far-field (or Kirsch) traction;
///   kBase:   a loaded edge lying on the (horizontal) bottom of the box;
///   kFree:   a face that became boundary because cells were removed (the
///            wall of the opening): no traction.
enum FaceLoad : unsigned int { kFree = 0, kLoaded = 1, kBase = 2 };

inline bool loaded(const dealii::TriaIterator<dealii::TriaAccessor<1, 2, 2>>& face) {
  return face->at_boundary() && face->user_index() != kFree;
}

std::uint64_t edge_key(int a, int b);

/// The bottom edge (faces tagged kBase) as a line load carrier: its length,
/// centroid and second moment about the centroid [m, m, m^3]. Throws
/// InputError (naming `who`) where the box has no such edge, since gravity
/// needs one to carry the weight the excavation removes.
struct BaseMoments {
  double length = 0, x = 0, inertia = 0;
};
BaseMoments base_moments(const dealii::Triangulation<2>& triangulation, const std::string& who);

/// Edges with exactly one triangle in the full mesh: the box.
std::unordered_set<std::uint64_t> outer_edges(const mesh::Mesh& mesh);

/// Between the mesh record and the triangulation.
struct GridMap {
  std::vector<int> cell_to_triangle;     ///< active cell index -> mesh triangle
  std::vector<int> grid_to_mesh_vertex;  ///< triangulation vertex -> mesh vertex
};

/// The triangulation of the triangles not `removed`, in the record's order,
/// with boundary ids from the mesh tags and FaceLoad user indices. Throws
/// InputError if nothing is left or the cells left fall apart.
GridMap build_triangulation(const mesh::Mesh& mesh, const std::vector<std::uint8_t>& removed,
                            const std::unordered_set<std::uint64_t>& outer,
                            dealii::Triangulation<2>& triangulation);

/// The three dofs that hold the rigid motions (see insitu_problem.cpp).
std::vector<dealii::types::global_dof_index> rigid_motion_pins(
    const dealii::DoFHandler<2>& dof_handler);

/// Vertex displacements in mesh order, less the rigid motion that best fits
/// the loaded boundary ("the far field stays put").
void displacement_without_rigid_motion(const dealii::DoFHandler<2>& dof_handler,
                                       const dealii::Vector<double>& solution,
                                       const std::vector<int>& grid_to_mesh_vertex,
                                       std::vector<double>& ux, std::vector<double>& uy);

/// sigma0 (tension positive) and its plane-strain zz component.
dealii::SymmetricTensor<2, 2> initial_stress(const InsituSpec& spec, const dealii::Point<2>& x);
double initial_szz(const InsituSpec& spec, const dealii::Point<2>& x);

/// UMFPACK; a singular matrix is reported as bad input.
void solve_direct(const dealii::SparseMatrix<double>& matrix, dealii::Vector<double>& x,
                  const dealii::Vector<double>& rhs);

}  // namespace rockfdem::insitu::grid
