// The contact gather: which pair entries each contact triangle sums.
//
// A detection leaves the pairs in canonical order and one CSR over them
// (rows in ascending triangle order). A local update after breakage appends
// its few new pairs instead of merging them in: a merge renumbers every pair
// after the first new one, and with it the whole CSR, so each update cost
// time in the pairs (two passes over all of them, serial) where it now costs
// time in the new ones. An appended pair's entries go into its triangles'
// short lists (a new row where a triangle had no pair) at their canonical
// places, and the gather merges a row's list with its CSR entries
// (each_gather_entry): every triangle sums its pairs in the order the
// merged pairs had, so the forces keep their bits however the pairs lie.
#include <algorithm>

#include "engine_data.hpp"

namespace rockfdem::fdem::detail {
namespace {

/// The base CSR over the sorted pairs [0, sorted_pairs): rows are the
/// candidates with such a pair, in candidate (ascending) order. Linear in
/// pairs and candidates; it looks the pairs' triangles up in a per-triangle
/// row array instead of searching the candidates.
void build_sorted_rows(EngineData& d) {
  ContactData& c = d.contact;
  const std::size_t np = c.sorted_pairs;
  std::vector<int>& row = c.breaks.gather_index;  // -1 between calls
  row.resize(d.tris.size(), -1);
  for (std::size_t q = 0; q < np; ++q) row[c.pairs[q][0]] = row[c.pairs[q][1]] = 0;
  c.gather_tri.clear();
  for (int t : c.candidates)
    if (row[t] == 0) {
      row[t] = static_cast<int>(c.gather_tri.size());
      c.gather_tri.push_back(t);
    }
  c.gather_start.assign(c.gather_tri.size() + 1, 0);
  for (std::size_t q = 0; q < np; ++q) {
    ++c.gather_start[row[c.pairs[q][0]] + 1];
    ++c.gather_start[row[c.pairs[q][1]] + 1];
  }
  for (std::size_t g = 0; g < c.gather_tri.size(); ++g) c.gather_start[g + 1] += c.gather_start[g];
  grow_to(c.gather_entry, 2 * np);
  std::vector<int>& next = c.grid.offset;  // grid scratch: free between detections
  next.assign(c.gather_start.begin(), c.gather_start.end() - 1);
  grow_to(c.entry_row, 2 * np);
  for (std::size_t q = 0; q < np; ++q)
    for (int side = 0; side < 2; ++side) {
      const int g = row[c.pairs[q][side]], entry = static_cast<int>(2 * q + side);
      c.gather_entry[next[g]++] = entry;
      c.entry_row[entry] = g;
    }
  for (int t : c.gather_tri) row[t] = -1;
}

/// Gather row of triangle t, a new one at the end where it has none.
int row_of(ContactData& c, int t) {
  const auto sorted_end = c.gather_tri.begin() + static_cast<long>(c.gather_start.size() - 1);
  const auto it = std::lower_bound(c.gather_tri.begin(), sorted_end, t);
  if (it != sorted_end && *it == t) return static_cast<int>(it - c.gather_tri.begin());
  const std::array<int, 2> key = {t, -1};
  const auto at = std::lower_bound(c.appended_rows.begin(), c.appended_rows.end(), key);
  if (at != c.appended_rows.end() && (*at)[0] == t) return (*at)[1];
  const int g = static_cast<int>(c.gather_tri.size());
  c.gather_tri.push_back(t);
  c.extra_head.push_back(-1);
  c.appended_rows.insert(at, {t, g});
  return g;
}

/// Links appended entry x (pair p) into row g's list at its canonical place.
void link_entry(ContactData& c, int g, int x, const std::array<int, 2>& p) {
  const int base = static_cast<int>(2 * c.sorted_pairs);
  int* at = &c.extra_head[g];
  while (*at >= 0 && c.pairs[(base + *at) / 2] < p) at = &c.extra_next[*at];
  c.extra_next[x] = *at;
  *at = x;
}

}  // namespace

void append_pair_entries(ContactData& c, std::size_t q) {
  grow_to(c.entry_row, 2 * (q + 1));
  for (int side = 0; side < 2; ++side) {
    const int g = row_of(c, c.pairs[q][side]);
    const int x = static_cast<int>(2 * (q - c.sorted_pairs)) + side;
    c.extra_next.resize(std::size_t(x) + 1, -1);
    link_entry(c, g, x, c.pairs[q]);
    c.entry_row[2 * q + side] = g;
  }
}

void build_gather(EngineData& d) {
  ContactData& c = d.contact;
  build_sorted_rows(d);
  c.extra_head.assign(c.gather_tri.size(), -1);
  c.extra_next.clear();
  c.appended_rows.clear();
  // The appended pairs in canonical order too (after a checkpoint is
  // loaded; local updates keep it themselves).
  c.appended_order.clear();
  for (std::size_t q = c.sorted_pairs; q < c.pairs.size(); ++q) {
    append_pair_entries(c, q);
    c.appended_order.push_back(static_cast<int>(q));
  }
  std::sort(c.appended_order.begin(), c.appended_order.end(), CanonicalOrder{c});
}

}  // namespace rockfdem::fdem::detail
