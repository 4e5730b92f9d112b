// What to mesh: the geometry and mesh sections of a scene, already validated
// by workflows/scene. Lengths in metres. The tunnel opening's bounding box is
// centred on the origin; the rock domain is centred on `domain_center`.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace rockfdem::mesh {

enum class ModelKind { kTunnel, kUcs, kBrazilian, kMshFile };
enum class TunnelShape { kCircular, kHorseshoe, kArched, kRectangular };

struct TunnelSpec {
  TunnelShape shape = TunnelShape::kHorseshoe;
  double radius = 0;    ///< circular
  double span = 11.3;   ///< horseshoe, arched, rectangular: width of the opening
  double height = 8.8;  ///< horseshoe, arched, rectangular: lowest floor point to crown
  double rise = 0;      ///< arched: rise of the arch above the walls (0 < rise <= span/2)
  double invert_rise =
      0;  ///< horseshoe, arched: depth of a curved invert below the walls' feet; 0: flat floor
  double lining_thickness = 0;  ///< 0: no lining ring
  /// Thickness of the ring's floor part (flat floor or invert arch), for
  /// horseshoe and arched openings; 0: lining_thickness.
  double invert_thickness = 0;
  double fracture_zone =
      0;  ///< crack elements allowed within this distance outside the opening; 0: none
};

struct DomainSpec {
  double width = 100;   ///< rock domain width
  double height = 100;  ///< rock domain height
  double center_x = 0;  ///< domain centre relative to the opening's centre
  double center_y = 0;
};

struct SpecimenSpec {
  double width = 0.05;       ///< UCS specimen width
  double height = 0.1;       ///< UCS specimen height
  double diameter = 0.05;    ///< Brazilian disc diameter
  double load_arc_deg = 10;  ///< Brazilian disc: angle of each loading arc
};

struct MshFileSpec {
  std::string path;                        ///< user's .msh file
  std::map<std::string, int> zone_groups;  ///< 2D physical group name -> Zone
  std::map<std::string, int> edge_groups;  ///< 1D physical group name -> EdgeTag
  std::string fracture_group;  ///< 2D physical group where cracks are allowed ("" = all rock)
  /// 1D physical groups whose lines are joints: each curve of them one
  /// trace (Mesh::joint_edges), numbered in this order, a group's curves
  /// by tag.
  std::vector<std::string> joint_groups;
};

struct MeshSizeSpec {
  double size_near = 0.5;       ///< element size at the tunnel boundary (specimens: everywhere)
  double size_far = 5.0;        ///< element size at the outer boundary
  double grading_distance = 0;  ///< distance from the tunnel over which size grows; 0: automatic
  int algorithm = 5;  ///< gmsh Mesh.Algorithm (5 = Delaunay: unstructured, see docs/meshing.md)
  int threads = 0;    ///< gmsh General.NumThreads (0 = OpenMP default)
};

/// A joint trace: a straight segment in the section plane [m], in the
/// model's frame (the opening's bounding box centred on the origin).
struct JointTrace {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct MeshSpec {
  ModelKind kind = ModelKind::kTunnel;
  TunnelSpec tunnel;
  DomainSpec domain;
  SpecimenSpec specimen;
  MshFileSpec msh;
  MeshSizeSpec size;
  /// Joint traces the tunnel mesh honours (conformal mesh lines), as
  /// given: build_mesh clips them (joints.hpp, prepare_joint_traces).
  std::vector<JointTrace> joints;
};

}  // namespace rockfdem::mesh
