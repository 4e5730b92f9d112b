// Meshing a MeshSpec with gmsh (OpenCASCADE kernel): tunnels in a rock
// rectangle, UCS specimens, Brazilian discs, or a user's own .msh file.
#pragma once

#include <cstddef>

#include "rockfdem/mesh/joints.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/mesh/mesh_spec.hpp"

namespace rockfdem::mesh {

/// Figures reported after meshing.
struct MeshReport {
  std::size_t n_triangles = 0;
  std::size_t n_vertices = 0;
  double min_altitude = 0;   ///< [m]
  double min_angle_deg = 0;  ///< [deg]
  double seconds = 0;        ///< wall time of build_mesh, gmsh start to Mesh record
  int gmsh_threads = 0;      ///< General.NumThreads given to gmsh
  JointTraceReport joints;   ///< what became of MeshSpec::joints (a .msh: its joint curves)
  /// The traces meshed (Mesh::joint_edges index them).
  std::vector<JointTrace> joint_traces;
};

/// Builds the mesh a spec describes.
/// @post triangles counter-clockwise, 3-node only, vertices numbered 0..n-1
///       with every vertex used; zone and fracture sized like triangles.
/// @post a generated mesh has its triangles in locality order (locality.hpp);
///       a .msh file's keep the file's order.
/// @post the OpenMP thread count is what it was before the call.
/// Throws rockfdem::InputError for a geometry that cannot be built (tunnel
/// outside the domain, lining thicker than the opening, a bad .msh file)
/// and std::runtime_error when gmsh fails otherwise.
Mesh build_mesh(const MeshSpec& spec, MeshReport* report = nullptr);

}  // namespace rockfdem::mesh
