// One gmsh session, opened and closed by scope. gmsh is a process-wide
// singleton with three habits we must contain here and nowhere else:
//   - gmsh::initialize() sets the process's OpenMP thread count to 1, and
//     meshing sets it to General.NumThreads: the session restores the count
//     it found, so no later stage (the engine) silently runs on one thread;
//   - it prints to the terminal unless told otherwise;
//   - it throws std::string, which no caller expects: `gmsh_guarded` turns
//     those into rockfdem::InputError or std::runtime_error.
#pragma once

#include <string>
#include <utility>

#include "rockfdem/error.hpp"

namespace rockfdem::mesh::detail {

class GmshSession {
 public:
  /// threads <= 0: as many as OpenMP would use now.
  explicit GmshSession(int threads, bool verbose = false);
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  int threads() const { return threads_; }

 private:
  int saved_omp_threads_ = 1;
  int threads_ = 1;
};

enum class GmshFailure { kInput, kRuntime };

/// Runs f(); a std::string thrown by gmsh becomes an InputError (kInput) or
/// std::runtime_error (kRuntime) whose message starts with `context`.
template <class F>
decltype(auto) gmsh_guarded(const std::string& context, GmshFailure kind, F&& f) {
  try {
    return std::forward<F>(f)();
  } catch (const std::string& what) {
    const std::string msg = context + ": gmsh: " + what;
    if (kind == GmshFailure::kInput) throw InputError(msg);
    throw std::runtime_error(msg);
  }
}

}  // namespace rockfdem::mesh::detail
