// How isotropic and how irregular a mesh is inside a band (the fracture
// zone): crack elements lie on mesh edges, so a mesh whose edges follow a
// few directions (a lattice) lets cracks run only along straight lattice
// lines. Two figures say whether that is so:
//   - the length-weighted histogram of edge orientations, each measured
//     against the local radial direction from the opening's centre (flat
//     for an isotropic mesh; peaks at 30, 90, 150 degrees for a lattice
//     laid in layers parallel to a circular opening);
//   - the fraction of interior nodes with exactly 6 neighbours (a regular
//     triangular lattice is ~100% valence 6; an unstructured Delaunay mesh
//     about a third to a half).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::mesh {

struct EdgeOrientation {
  /// Bin k holds the length share of edges whose angle to the radial
  /// direction, taken modulo 180 degrees, lies within half a bin of
  /// k * 180 / n_bins degrees (bins centred on 0, 15, 30, ... for 12 bins).
  /// Sums to 1. Flat: every bin 1 / n_bins.
  std::vector<double> histogram;
  /// max over bins of |histogram[k] * n_bins - 1|: 0 for a flat histogram,
  /// 0.1 when the fullest or emptiest bin is 10% off the mean.
  double max_deviation = 0;
  /// |length-weighted mean of exp(i 6 phi)|: 1 for a hexagonal lattice laid
  /// along the radial (or tangential) direction, ~0 when isotropic.
  double hexatic_order = 0;
  /// |length-weighted mean of exp(i 2 phi)|: directional bias (radial or
  /// tangential edges preferred), ~0 when isotropic.
  double directional_bias = 0;
  /// Share of the band's interior nodes (every incident triangle in the
  /// band) with exactly 6 neighbours.
  double valence6_fraction = 0;
  /// Smallest triangle altitude inside the band [m].
  double min_altitude = 0;
  /// Smallest interior angle inside the band [deg].
  double min_angle_deg = 0;
  std::size_t n_edges = 0;           ///< edges between two of the band's triangles
  std::size_t n_interior_nodes = 0;  ///< nodes counted for valence6_fraction
};

/// Measures the triangles with in_band[t] != 0 (e.g. `m.fracture`), angles
/// taken against the direction from (cx, cy) to each edge's midpoint.
/// @pre in_band.size() == m.n_triangles(), n_bins >= 2.
EdgeOrientation measure_edge_orientation(const Mesh& m, const std::vector<std::uint8_t>& in_band,
                                         double cx, double cy, int n_bins = 12);

}  // namespace rockfdem::mesh
