// The ranks of a study launched with `mpirun -np N rockfdem sweep|calibrate`
// (or a scheduler's launcher): each runs whole variants with its own -j
// threads; nothing below this file knows of MPI. Without mpirun the process
// is a singleton (MPI is started by main for the implicit stage's solver
// anyway) and every call here reduces to a plain loop.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace rockfdem::workflows::study {

int rank();
int n_ranks();

/// Runs job(i) for every i < n, spread over the ranks: rank 0 hands the
/// next index to whichever rank asks first (a counter on rank 0, taken with
/// an atomic fetch-and-add), so slow and fast variants balance. Returns on
/// rank 0 the results in index order, whichever rank ran which; empty on
/// the other ranks. Every rank must call it with the same n. A job that
/// throws ends the whole study (MPI_Abort) where there are other ranks.
std::vector<std::string> farm(std::size_t n, const std::function<std::string(std::size_t)>& job);

/// Runs `f`; where there are other ranks, an exception in it ends them all
/// (MPI_Abort with the exit code main() would give) instead of leaving them
/// waiting for this one.
void or_abort_all(const std::function<void()>& f);

/// Rank 0 sends `text` to every rank; every rank returns it. Waiting ranks
/// sleep between polls instead of spinning, leaving the cores to the runs.
std::string broadcast(const std::string& text);

}  // namespace rockfdem::workflows::study
