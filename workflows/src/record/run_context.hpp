// What one run (run, mesh, insitu, check, or a study's variant) takes from
// its command line: made once by the command and passed to what needs it.
#pragma once

#include <string>
#include <utility>

namespace rockfdem::workflows {

struct CommandLine;

struct RunContext {
  int threads = 1;  ///< OpenMP threads (the engine's and the libraries'), resolved: > 0
  std::string output_dir = "rockfdem-out";
  bool quiet = false;
  bool force = false;          ///< overwrite another scene's results in output_dir
  std::string restart;         ///< checkpoint to continue from; empty: start afresh
  long checkpoint_every = -1;  ///< steps between checkpoints; -1: the scene's
  bool force_dt = false;       ///< accept an engine.dt above the stability limit
};

/// The command line's run settings; -j 0 (all cores) becomes the core count.
RunContext run_context(const CommandLine& cli);

/// Holds OpenMP's thread count at `threads` from construction to the end
/// of its scope, whatever a library call in between sets (gmsh and
/// Trilinos' Kokkos may change it).
class OmpThreads {
 public:
  explicit OmpThreads(int threads);
  ~OmpThreads();
  OmpThreads(const OmpThreads&) = delete;
  OmpThreads& operator=(const OmpThreads&) = delete;

 private:
  int threads_;
};

/// f() with OpenMP's thread count put back to the context's afterwards.
template <class F>
auto keeping_threads(const RunContext& ctx, F&& f) -> decltype(f()) {
  const OmpThreads keep(ctx.threads);
  return std::forward<F>(f)();
}

}  // namespace rockfdem::workflows
