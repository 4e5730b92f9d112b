// Joint traces in the section plane: sets generated from their statistics
// (deterministic: a seed gives the same traces on any machine and thread
// count) and the preparation that makes any list of traces meshable
// (clipped to the rock, slivers removed). No gmsh here.
#pragma once

#include <cstdint>
#include <vector>

#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/mesh/mesh_spec.hpp"

namespace rockfdem::mesh {

/// One joint set. Traces run at `dip_deg` below the horizontal, dipping
/// towards +x (0 horizontal, 90 vertical, up to 180 dipping towards -x),
/// on parallel lines `spacing` apart (perpendicular). On each line traces
/// of `trace_length` cover the fraction `persistence` of it (rock bridges
/// between them); trace_length 0: continuous lines. Scatter, uniform and
/// per line (dip, spacing) or per trace (length): +-dip_scatter_deg,
/// +-spacing_scatter x spacing, +-length_scatter x trace_length. The first
/// line's offset and each line's first trace's start are uniform random.
struct JointSetSpec {
  double dip_deg = 0;
  double spacing = 1;
  double trace_length = 0;
  double persistence = 1;
  double dip_scatter_deg = 0;
  double spacing_scatter = 0;
  double length_scatter = 0;
};

/// Rectangle the sets fill [m].
struct JointRegion {
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
};

/// The traces of set `set` clipped to `region`; the draws come from a
/// splitmix64 stream of (seed, set index).
std::vector<JointTrace> generate_joint_set(const JointSetSpec& set, const JointRegion& region,
                                           std::uint64_t seed, int set_index);

/// What prepare_joint_traces did.
struct JointTraceReport {
  long given = 0;        ///< traces handed in
  long outside = 0;      ///< wholly outside the rock (domain or opening): dropped
  long split = 0;        ///< cut in two by the opening
  long merged = 0;       ///< near-coincident with another trace: merged into it
  long snapped = 0;      ///< ends moved onto a trace, the opening or the domain side nearby
  long too_short = 0;    ///< shorter than the tolerance after clipping: dropped
  long kept = 0;         ///< traces meshed
  double tolerance = 0;  ///< the sliver tolerance used [m]: size_near / 4
  double length = 0;     ///< total length of the kept traces [m]
};

/// The traces a tunnel mesh can honour: each clipped to the rock domain and
/// out of the opening (a trace crossing the opening becomes two), then
/// slivers removed at tolerance tol = size_near / 4, which would otherwise
/// force tiny elements: an end within tol of the opening, a domain side or
/// another trace moves onto it (a T junction, exact); a trace lying within
/// tol of another (both ends, nearly parallel, overlapping) is merged into
/// it (the union along the first); pieces shorter than tol are dropped.
std::vector<JointTrace> prepare_joint_traces(const MeshSpec& spec,
                                             const std::vector<JointTrace>& traces,
                                             JointTraceReport* report = nullptr);

/// The traces of a mesh whose joint edges came from a user's .msh (its
/// joint groups' curves, msh_io.hpp): trace k runs between the two ends of
/// its edges' path, the lower vertex index first (a closed curve: its first
/// edge's first vertex and last edge's second). The report counts them as
/// given and kept, with the length of their chords.
std::vector<JointTrace> traces_of_joint_edges(const Mesh& m, JointTraceReport* report = nullptr);

/// Length of a trace [m].
double trace_length(const JointTrace& t);

}  // namespace rockfdem::mesh
