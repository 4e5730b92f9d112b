// Broad phase of contact: which boxes overlap, by a uniform cell grid built
// with a counting sort (linear cost, deterministic for any thread count).
#pragma once

#include <array>
#include <vector>

namespace rockfdem::fdem::detail {

/// Reused between detections so that a warmed-up run allocates nothing.
struct GridScratch {
  std::vector<int> cell, cell_start, items, count, offset;
  std::vector<std::array<int, 2>> found;
};

/// Keeps pair (i, j), i < j, of overlapping boxes when it returns true.
using PairFilter = bool (*)(const void* context, int i, int j);

/// All pairs (i, j), i < j, whose boxes (xmin, ymin, xmax, ymax; 4 per item)
/// overlap and that `keep` accepts, sorted by (i, j). Boxes are put in the
/// cell of their centre; the cell is at least the largest box extent, so
/// overlapping boxes lie in the same or adjacent cells. The grid is coarsened
/// when the boxes are spread out, so it never has more than about 4 cells
/// per box.
void grid_pairs(const std::vector<double>& boxes, PairFilter keep, const void* context, int threads,
                GridScratch& scratch, std::vector<std::array<int, 2>>& pairs);

/// The same pairs by testing every pair (tests).
void brute_force_pairs(const std::vector<double>& boxes, PairFilter keep, const void* context,
                       std::vector<std::array<int, 2>>& pairs);

}  // namespace rockfdem::fdem::detail
