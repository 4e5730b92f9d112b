// The few OpenMP helpers the loops share. Only .cpp files include this: no
// OpenMP type appears in a public header.
#pragma once

#include <omp.h>

#include <vector>

namespace rockfdem::fdem::detail {

/// Thread count for a parallel loop: the engine's setting, or OpenMP's default.
inline int thread_count(int requested) { return requested > 0 ? requested : omp_get_max_threads(); }

/// Fixed block size of deterministic global sums: partial sums over blocks of
/// this many items are added in block order, whatever the thread count.
constexpr long kSumBlock = 4096;

/// Node-loop block: small enough that 16 threads get several blocks each on
/// a 33k-triangle model.
constexpr long kNodeBlock = 512;

/// Deterministic parallel sum of f(i) over [0, n): the blocks of `block`
/// items are fixed, each block is summed serially, and the block sums are
/// added in order.
template <class F>
double block_sum(long n, int threads, F&& f, long block = kSumBlock) {
  const long n_blocks = (n + block - 1) / block;
  // On the stack up to 4096 blocks (32 KiB): no allocation in the time
  // loop below 16M items, 2M nodes in the node loop's blocks.
  constexpr long kStackBlocks = 4096;
  double partial_stack[kStackBlocks];
  double* partial = partial_stack;
  std::vector<double> heap;
  if (n_blocks > kStackBlocks) {
    heap.assign(n_blocks, 0.0);
    partial = heap.data();
  }
#pragma omp parallel for schedule(static) num_threads(thread_count(threads))
  for (long b = 0; b < n_blocks; ++b) {
    const long end = b * block + block < n ? b * block + block : n;
    double s = 0;
    for (long i = b * block; i < end; ++i) s += f(i);
    partial[b] = s;
  }
  double total = 0;
  for (long b = 0; b < n_blocks; ++b) total += partial[b];
  return total;
}

}  // namespace rockfdem::fdem::detail
