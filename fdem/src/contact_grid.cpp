// Cell-grid broad phase (reference sec. 3: Munjiza's NBS does the same with
// linked lists; a counting sort gives the same linear cost and parallelises).
//
// Determinism: items are bucketed in ascending order, every item i lists its
// partners j > i from the 3 x 3 cells around it (then sorts that short list),
// and the lists are concatenated in item order after a count pass: the
// output depends on the boxes only, never on the thread count.
#include "contact_grid.hpp"

#include <algorithm>
#include <cmath>

#include "parallel.hpp"

namespace rockfdem::fdem::detail {
namespace {

inline bool overlap(const double* a, const double* b) {
  return a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3];
}

struct Grid {
  double x0 = 0, y0 = 0, inv_cell = 1;
  long nx = 1, ny = 1;
};

/// Cell size from the largest box, coarsened to at most ~4 cells per box.
Grid make_grid(const std::vector<double>& boxes, long n) {
  double ext = 0, cx0 = 1e300, cy0 = 1e300, cx1 = -1e300, cy1 = -1e300;
  for (long i = 0; i < n; ++i) {
    const double* b = &boxes[4 * i];
    ext = std::max({ext, b[2] - b[0], b[3] - b[1]});
    const double cx = 0.5 * (b[0] + b[2]), cy = 0.5 * (b[1] + b[3]);
    cx0 = std::min(cx0, cx);
    cy0 = std::min(cy0, cy);
    cx1 = std::max(cx1, cx);
    cy1 = std::max(cy1, cy);
  }
  Grid g;
  double cell = ext > 0 ? ext : 1.0;
  const double w = cx1 - cx0, h = cy1 - cy0;
  const double max_cells = 4.0 * n + 16.0;
  if ((w / cell + 1) * (h / cell + 1) > max_cells)
    cell = std::max(cell, std::sqrt(std::max(w, cell) * std::max(h, cell) / max_cells) * 1.01);
  while ((w / cell + 1) * (h / cell + 1) > max_cells) cell *= 1.5;
  g.x0 = cx0;
  g.y0 = cy0;
  g.inv_cell = 1.0 / cell;
  g.nx = static_cast<long>(w * g.inv_cell) + 1;
  g.ny = static_cast<long>(h * g.inv_cell) + 1;
  return g;
}

/// Counting sort of the items by cell: cell_start (CSR) and items, each
/// cell's items in ascending order.
void bucket(const std::vector<double>& boxes, long n, const Grid& g, GridScratch& s) {
  s.cell.resize(n);
  const long n_cells = g.nx * g.ny;
  s.cell_start.assign(n_cells + 1, 0);
  for (long i = 0; i < n; ++i) {
    const double* b = &boxes[4 * i];
    const long cx =
        std::min(g.nx - 1, static_cast<long>((0.5 * (b[0] + b[2]) - g.x0) * g.inv_cell));
    const long cy =
        std::min(g.ny - 1, static_cast<long>((0.5 * (b[1] + b[3]) - g.y0) * g.inv_cell));
    s.cell[i] = static_cast<int>(cy * g.nx + cx);
    ++s.cell_start[s.cell[i] + 1];
  }
  for (long c = 0; c < n_cells; ++c) s.cell_start[c + 1] += s.cell_start[c];
  s.items.resize(n);
  s.offset.assign(s.cell_start.begin(), s.cell_start.end() - 1);
  for (long i = 0; i < n; ++i) s.items[s.offset[s.cell[i]]++] = static_cast<int>(i);
}

/// Partners j > i of item i; writes them to out (if given), returns the count.
template <bool kWrite>
int partners(const std::vector<double>& boxes, const Grid& g, const GridScratch& s, PairFilter keep,
             const void* context, long i, std::array<int, 2>* out) {
  const long c = s.cell[i], cx = c % g.nx, cy = c / g.nx;
  int n = 0;
  for (long y = std::max(0L, cy - 1); y <= std::min(g.ny - 1, cy + 1); ++y)
    for (long x = std::max(0L, cx - 1); x <= std::min(g.nx - 1, cx + 1); ++x) {
      const long cell = y * g.nx + x;
      for (int k = s.cell_start[cell]; k < s.cell_start[cell + 1]; ++k) {
        const int j = s.items[k];
        if (j <= i || !overlap(&boxes[4 * i], &boxes[4 * j])) continue;
        if (!keep(context, static_cast<int>(i), j)) continue;
        if (kWrite) out[n] = {static_cast<int>(i), j};
        ++n;
      }
    }
  if (kWrite) std::sort(out, out + n, [](const auto& p, const auto& q) { return p[1] < q[1]; });
  return n;
}

}  // namespace

void grid_pairs(const std::vector<double>& boxes, PairFilter keep, const void* context, int threads,
                GridScratch& s, std::vector<std::array<int, 2>>& pairs) {
  const long n = static_cast<long>(boxes.size() / 4);
  pairs.clear();
  if (n < 2) return;
  const Grid g = make_grid(boxes, n);
  bucket(boxes, n, g, s);
  s.count.resize(n + 1);
#pragma omp parallel for schedule(dynamic, 256) num_threads(thread_count(threads)) if (n > 2048)
  for (long i = 0; i < n; ++i)
    s.count[i + 1] = partners<false>(boxes, g, s, keep, context, i, nullptr);
  s.count[0] = 0;
  for (long i = 0; i < n; ++i) s.count[i + 1] += s.count[i];
  pairs.resize(s.count[n]);
#pragma omp parallel for schedule(dynamic, 256) num_threads(thread_count(threads)) if (n > 2048)
  for (long i = 0; i < n; ++i)
    partners<true>(boxes, g, s, keep, context, i, pairs.data() + s.count[i]);
}

void brute_force_pairs(const std::vector<double>& boxes, PairFilter keep, const void* context,
                       std::vector<std::array<int, 2>>& pairs) {
  const int n = static_cast<int>(boxes.size() / 4);
  pairs.clear();
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (overlap(&boxes[4 * i], &boxes[4 * j]) && keep(context, i, j)) pairs.push_back({i, j});
}

}  // namespace rockfdem::fdem::detail
