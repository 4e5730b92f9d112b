// Rockbolts as plain records and the marking of the mesh triangles each
// bolt occupies (seed sec. 2.2.1, eq. 3).
//
//   std::vector<Bolt> bolts = {Bolt{a, b, d}, bolt_from_head(head, dir, length, d)};
//   BoltMarks marks = mark_bolts(input, bolts);           // per bolt, ordered along the axis
//
// Marking rule (exact for any orientation, deterministic in the touching
// cases). A bolt is the rectangle of width d around its axis A->B; its long
// sides are the axis offset by +-d/2. "Enters" means passes through the
// triangle's open interior: the seed's crossing test (eq. 3) extended so
// that an end point inside a triangle, or a segment entering it through a
// vertex, also counts; touching (along an edge, through a vertex without
// entering, ending on the boundary) does not.
//   Centre line (every bolt): the triangles it enters; where it passes
//     through a mesh vertex strictly between A and B, also the triangles
//     around that vertex on its left (+n = axis turned 90 deg ccw); where it
//     runs along a mesh edge, the triangle on the edge's left. So the marked
//     chain always shares edges (crack elements) from head to end.
//   Wide bolts (d at least the median edge length of the triangles the
//     centre line marks), in addition: the triangles either long side
//     enters, and those whose centroid lies strictly inside the rectangle
//     (wholly inside, crossed by no side).
// So a thin bolt marks the chain its centre line crosses; a bolt whose long
// sides run along mesh lines marks exactly the row between them. Signed
// distances within 1e-12 of the segment and edge lengths count as zero, so
// coordinates equal up to rounding behave as equal.
#pragma once

#include <array>
#include <vector>

#include "rockfdem/fdem/model_input.hpp"

namespace rockfdem::fdem {

using Point2 = std::array<double, 2>;

/// One bolt: head A (on the excavation boundary), end B (in the rock),
/// diameter d [m]. The axis runs A -> B.
struct Bolt {
  Point2 a{};
  Point2 b{};
  double diameter = 0.025;
};

/// A bolt from its head point, a direction (need not be unit) and a length.
Bolt bolt_from_head(const Point2& head, const Point2& direction, double length, double diameter);

/// Which triangles each bolt occupies.
struct BoltMarks {
  /// Per bolt: its triangles ordered by the position of their centroid along
  /// the axis (ties by index), so outputs read head to end.
  std::vector<std::vector<int>> triangles;
  /// Per triangle: the lowest-numbered bolt that marks it, -1 for rock.
  std::vector<int> owner;
};

/// Marks the triangles of every bolt (rule above). Throws InputError for a
/// bolt with non-positive diameter or zero length. A uniform cell grid
/// limits the exact tests to triangles near each bolt.
BoltMarks mark_bolts(const std::vector<double>& x, const std::vector<double>& y,
                     const std::vector<std::array<int, 3>>& triangles,
                     const std::vector<Bolt>& bolts);
BoltMarks mark_bolts(const ModelInput& input, const std::vector<Bolt>& bolts);

/// Whether the closed segment p-q passes through the open interior of the
/// triangle (v0, v1, v2) (counter-clockwise or not): the exact test behind
/// rule (1), exposed for tests and tools.
bool segment_enters_triangle(const Point2& p, const Point2& q, const Point2& v0, const Point2& v1,
                             const Point2& v2);

}  // namespace rockfdem::fdem
