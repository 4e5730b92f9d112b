// Lists of the few nodes that carry something (a boundary record, a dead
// load), ascending, instead of an entry for every node: a search where a
// node is asked for alone, a cursor where the node loop walks them in order.
#pragma once

#include <algorithm>
#include <vector>

namespace rockfdem::fdem::detail {

/// Position of node i in the ascending `list`, or -1.
inline long index_in(const std::vector<int>& list, long i) {
  const auto it = std::lower_bound(list.begin(), list.end(), int(i));
  return it != list.end() && *it == i ? long(it - list.begin()) : -1;
}

/// Walks an ascending node list along ascending nodes from `first` on: one
/// search, then a step per node.
class NodeListCursor {
 public:
  NodeListCursor(const std::vector<int>& list, long first)
      : list_(list), k_(std::lower_bound(list.begin(), list.end(), int(first)) - list.begin()) {}
  /// Position of node i in the list, or -1; i not below the last node asked for.
  long at(long i) {
    const long n = static_cast<long>(list_.size());
    while (k_ < n && list_[k_] < i) ++k_;
    return k_ < n && list_[k_] == i ? k_ : -1;
  }

 private:
  const std::vector<int>& list_;
  long k_;
};

}  // namespace rockfdem::fdem::detail
