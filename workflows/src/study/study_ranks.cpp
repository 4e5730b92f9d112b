#include "study/study_ranks.hpp"

#include <mpi.h>

#include <chrono>
#include <iostream>
#include <thread>
#include <utility>

#include "rockfdem/error.hpp"
#include "run/interrupt.hpp"

namespace rockfdem::workflows::study {
namespace {

// MPI's blocking calls poll at full speed; a waiting rank would take a core
// from the runs on its node.
void wait_gently(MPI_Request& request) {
  int done = 0;
  for (MPI_Test(&request, &done, MPI_STATUS_IGNORE); !done;
       MPI_Test(&request, &done, MPI_STATUS_IGNORE))
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
}

void barrier_gently() {
  MPI_Request r;
  MPI_Ibarrier(MPI_COMM_WORLD, &r);
  wait_gently(r);
}

// Rank 0 collects every rank's (index, result) pairs.
std::vector<std::string> gather(const std::vector<std::pair<long, std::string>>& mine,
                                std::size_t n) {
  std::string packed;
  for (const auto& [i, text] : mine)
    packed += std::to_string(i) + ' ' + std::to_string(text.size()) + ' ' + text;
  int length = int(packed.size());
  std::vector<int> lengths(static_cast<std::size_t>(n_ranks())), offsets(lengths.size());
  MPI_Request r;
  MPI_Igather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD, &r);
  wait_gently(r);
  std::string all;
  if (rank() == 0) {
    for (std::size_t k = 1; k < lengths.size(); ++k) offsets[k] = offsets[k - 1] + lengths[k - 1];
    all.resize(std::size_t(offsets.back() + lengths.back()));
  }
  MPI_Igatherv(packed.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(),
               MPI_CHAR, 0, MPI_COMM_WORLD, &r);
  wait_gently(r);
  std::vector<std::string> results(rank() == 0 ? n : 0);
  for (std::size_t at = 0; at < all.size();) {
    std::size_t used = 0;
    const long i = std::stol(all.substr(at), &used);
    at += used + 1;
    const std::size_t size = std::stoul(all.substr(at, 24), &used);
    at += used + 1;
    results[std::size_t(i)] = all.substr(at, size);
    at += size;
  }
  return results;
}

}  // namespace

int rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int n_ranks() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

std::vector<std::string> farm(std::size_t n, const std::function<std::string(std::size_t)>& job) {
  if (n_ranks() == 1) {
    std::vector<std::string> results;
    for (std::size_t i = 0; i < n; ++i) results.push_back(job(i));
    return results;
  }
  long* next = nullptr;
  MPI_Win window;
  MPI_Win_allocate(rank() == 0 ? sizeof(long) : 0, sizeof(long), MPI_INFO_NULL, MPI_COMM_WORLD,
                   &next, &window);
  if (rank() == 0) *next = 0;
  barrier_gently();  // the counter is set before anyone takes from it
  MPI_Win_lock_all(0, window);
  std::vector<std::pair<long, std::string>> mine;
  for (;;) {
    const long one = 1;
    long i = 0;
    MPI_Fetch_and_op(&one, &i, MPI_LONG, 0, 0, MPI_SUM, window);
    MPI_Win_flush(0, window);
    if (i >= long(n)) break;
    std::string result;
    or_abort_all([&] { result = job(std::size_t(i)); });
    mine.push_back({i, result});
  }
  MPI_Win_unlock_all(window);
  std::vector<std::string> results = gather(mine, n);
  barrier_gently();  // MPI_Win_free waits for every rank, spinning
  MPI_Win_free(&window);
  return results;
}

void or_abort_all(const std::function<void()>& f) {
  if (n_ranks() == 1) return f();
  try {
    f();
  } catch (const Interrupted& e) {
    std::cerr << "rockfdem: rank " << rank() << ": " << e.what() << '\n';
    MPI_Abort(MPI_COMM_WORLD, e.exit_code());
  } catch (const InputError& e) {
    std::cerr << "rockfdem: error: rank " << rank() << ": " << e.what() << '\n';
    MPI_Abort(MPI_COMM_WORLD, 2);
  } catch (const std::exception& e) {
    std::cerr << "rockfdem: rank " << rank() << ": " << e.what() << '\n';
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
}

std::string broadcast(const std::string& text) {
  if (n_ranks() == 1) return text;
  long length = long(text.size());
  MPI_Request r;
  MPI_Ibcast(&length, 1, MPI_LONG, 0, MPI_COMM_WORLD, &r);
  wait_gently(r);
  std::string out = rank() == 0 ? text : std::string(std::size_t(length), '\0');
  MPI_Ibcast(out.data(), int(length), MPI_CHAR, 0, MPI_COMM_WORLD, &r);
  wait_gently(r);
  return out;
}

}  // namespace rockfdem::workflows::study
