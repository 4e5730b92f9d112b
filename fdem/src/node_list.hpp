// Lists of the few nodes that carry something (a boundary record, a dead
// load), ascending, instead of an entry for every node: a search where a
// node is asked for alone, a cursor where the node loop walks them in order.
#pragma once

#include <algorithm>
#include <limits>
#include <vector>

namespace rockfdem::fdem::detail {

/// Position of node i in the ascending `list`, or -1.
inline long index_in(const std::vector<int>& list, long i) {
  const auto it = std::lower_bound(list.begin(), list.end(), int(i));
  return it != list.end() && *it == i ? long(it - list.begin()) : -1;
}

/// Walks an ascending node list along ascending nodes from `first` on: one
/// search, then, per node, one comparison with the next listed node (the
/// node loop asks for every node, nearly all of them unlisted).
class NodeListCursor {
 public:
  NodeListCursor(const std::vector<int>& list, long first)
      : list_(list.data()),
        size_(static_cast<long>(list.size())),
        k_(std::lower_bound(list.begin(), list.end(), int(first)) - list.begin()),
        next_(listed(k_)) {}
  /// Position of node i in the list, or -1; i not below the last node asked for.
  long at(long i) {
    if (i < next_) return -1;
    while (next_ < i) next_ = listed(++k_);
    return next_ == i ? k_ : -1;
  }

 private:
  /// The k-th listed node, or past every node when the list ends there.
  long listed(long k) const { return k < size_ ? list_[k] : std::numeric_limits<long>::max(); }
  const int* list_;
  long size_, k_, next_;
};

}  // namespace rockfdem::fdem::detail
