#include "outputs/rock_locator.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace rockfdem::workflows {
namespace {

/// (x, y) on or left of every edge of the counter-clockwise triangle t.
bool contains(const mesh::Mesh& m, std::size_t t, double x, double y) {
  const auto& tri = m.triangles[t];
  for (int k = 0; k < 3; ++k) {
    const int a = tri[k], b = tri[(k + 1) % 3];
    if (!((m.x[b] - m.x[a]) * (y - m.y[a]) - (m.y[b] - m.y[a]) * (x - m.x[a]) >= 0)) return false;
  }
  return true;
}

}  // namespace

int RockLocator::cell_of(double v, double v0, int n) const {
  return std::clamp(int(std::floor((v - v0) / cell_)), 0, n - 1);
}

RockLocator::RockLocator(const mesh::Mesh& m) : m_(m) {
  std::vector<std::size_t> rock;
  double x1 = -INFINITY, y1 = -INFINITY;
  x0_ = y0_ = INFINITY;
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (m.zone[t] != mesh::kRock) continue;
    rock.push_back(t);
    for (int v : m.triangles[t]) {
      x0_ = std::min(x0_, m.x[v]), x1 = std::max(x1, m.x[v]);
      y0_ = std::min(y0_, m.y[v]), y1 = std::max(y1, m.y[v]);
    }
  }
  if (rock.empty()) return;
  // About two triangles per cell.
  cell_ = std::max(std::sqrt((x1 - x0_) * (y1 - y0_) / (0.5 * double(rock.size()))), 1e-12);
  nx_ = int((x1 - x0_) / cell_) + 1, ny_ = int((y1 - y0_) / cell_) + 1;
  // Each triangle in every cell its bounding box touches; counted, then placed
  // in triangle order, so that a cell's list ascends.
  std::vector<std::array<int, 4>> box(rock.size());
  start_.assign(std::size_t(nx_) * ny_ + 1, 0);
  for (std::size_t i = 0; i < rock.size(); ++i) {
    const auto& tri = m.triangles[rock[i]];
    double bx0 = INFINITY, bx1 = -INFINITY, by0 = INFINITY, by1 = -INFINITY;
    for (int v : tri) {
      bx0 = std::min(bx0, m.x[v]), bx1 = std::max(bx1, m.x[v]);
      by0 = std::min(by0, m.y[v]), by1 = std::max(by1, m.y[v]);
    }
    box[i] = {cell_of(bx0, x0_, nx_), cell_of(bx1, x0_, nx_), cell_of(by0, y0_, ny_),
              cell_of(by1, y0_, ny_)};
    for (int cy = box[i][2]; cy <= box[i][3]; ++cy)
      for (int cx = box[i][0]; cx <= box[i][1]; ++cx) ++start_[std::size_t(cy) * nx_ + cx + 1];
  }
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  items_.resize(std::size_t(start_.back()));
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < rock.size(); ++i)
    for (int cy = box[i][2]; cy <= box[i][3]; ++cy)
      for (int cx = box[i][0]; cx <= box[i][1]; ++cx)
        items_[std::size_t(fill[std::size_t(cy) * nx_ + cx]++)] = int(rock[i]);
}

int RockLocator::at(double x, double y) const {
  if (nx_ == 0 || !(x >= x0_ && y >= y0_ && x <= x0_ + nx_ * cell_ && y <= y0_ + ny_ * cell_))
    return -1;
  const std::size_t c = std::size_t(cell_of(y, y0_, ny_)) * nx_ + cell_of(x, x0_, nx_);
  for (int k = start_[c]; k < start_[c + 1]; ++k)
    if (contains(m_, std::size_t(items_[k]), x, y)) return items_[k];
  return -1;
}

}  // namespace rockfdem::workflows
