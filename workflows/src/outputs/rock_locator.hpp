// Which rock triangle holds a point: a uniform grid of the rock triangles'
// bounding boxes, built once, so that the continuum profiles' 360 look-ups
// along their rays do not each scan a 420k-triangle mesh.
#pragma once

#include <vector>

#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::workflows {

class RockLocator {
 public:
  explicit RockLocator(const mesh::Mesh& m);

  /// The lowest-numbered rock triangle containing (x, y) (edges and corners
  /// included, as a scan in triangle order finds it), -1 if none.
  int at(double x, double y) const;

 private:
  const mesh::Mesh& m_;
  double x0_ = 0, y0_ = 0, cell_ = 1;
  int nx_ = 0, ny_ = 0;
  std::vector<int> start_, items_;  ///< cell c holds items_[start_[c] .. start_[c + 1])
  int cell_of(double v, double v0, int n) const;
};

}  // namespace rockfdem::workflows
