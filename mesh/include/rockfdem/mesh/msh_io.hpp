// gmsh .msh files in and out. Written files carry physical groups named
// for the zones ("rock", "core", "lining", "fracture"), edge tags
// ("bottom", "right", "top", "left", "excavation", "lining_inner", "rim",
// "load_top", "load_bottom", "edge_<tag>" for user tags) and joints
// ("joints", a curve per trace), so read_msh with empty group maps reads
// back exactly what write_msh wrote.
#pragma once

#include <string>

#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/mesh/mesh_spec.hpp"

namespace rockfdem::mesh {

/// Writes `m` as a gmsh 4.1 ASCII file through gmsh's own writer, to a
/// temporary file beside `path` renamed over it at the end, so a reader
/// never sees half a file. Throws std::runtime_error naming the path when
/// it cannot be written.
void write_msh(const Mesh& m, const std::string& path);

/// Reads a user's .msh (any version gmsh reads). 2D physical groups named in
/// `spec.zone_groups` become zones, 1D groups in `spec.edge_groups` edge
/// tags; with both maps empty the names write_msh uses are taken. The lines
/// of the 1D groups in `spec.joint_groups` (with all three empty,
/// write_msh's "joints") become Mesh::joint_edges, each curve one trace
/// (traces_of_joint_edges in joints.hpp gives their ends). Triangles in
/// `spec.fracture_group` (all rock triangles when "") get fracture = 1.
/// Clockwise triangles are turned counter-clockwise.
/// Throws rockfdem::InputError naming the file and the group, node or
/// element at fault for: a missing or unreadable file, a missing physical
/// group, an element type other than 3-node triangles and 2-node lines,
/// NaN or infinite coordinates, two nodes at one position, a zero-area
/// triangle, a triangle in no zone group, a joint group without lines or
/// with a line that is not an edge between two triangles.
/// gmsh reads the file in a forked child process (the checks before gmsh
/// run in this one): a crash of gmsh's reader (a signal), a read longer
/// than 60 s + 4 s per MiB, or a record from the child that is cut short or
/// out of bounds is an InputError naming the file; this process's gmsh and
/// OpenMP state are untouched. Throws std::runtime_error when no child
/// process can be started.
Mesh read_msh(const MshFileSpec& spec);

/// Every zone and every edge tag with a name, in number order: what name
/// lookups (zone_name, edge_tag_name below) run over.
inline constexpr Zone kZones[] = {kRock, kCore, kLining};
inline constexpr EdgeTag kEdgeTags[] = {kBottom,      kRight, kTop,     kLeft,      kExcavation,
                                        kLiningInner, kRim,   kLoadTop, kLoadBottom};

/// The physical-group name write_msh uses for an edge tag ("edge_<tag>"
/// for tags it has no name for).
std::string edge_tag_name(int tag);

/// The physical-group name write_msh uses for a zone ("zone_<n>" for
/// numbers that are no Zone).
std::string zone_name(int zone);

}  // namespace rockfdem::mesh
