// Private: `rockfdem check`'s probe. The scene's real mesh and engine are
// built and stepped a few hundred times, so that the figures check prints
// (time steps, memory, run time) come from this mesh and this machine
// rather than from nominal sizes and constants.
#pragma once

#include <cstddef>
#include <string>

#include "record/run_context.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

struct Probe {
  std::size_t triangles = 0;
  std::size_t fracture_triangles = 0;
  double min_altitude = 0;      ///< smallest triangle altitude of the mesh [m]
  double mesh_seconds = 0;      ///< building the mesh [s]
  double dt_start = 0;          ///< the engine's step at the start (hand-off) [s]
  double dt_stages = 0;         ///< its step with the stages' damping [s]
  double critical_true = 0;     ///< stability limit on true masses at the start [s]
  long steps = 0;               ///< explicit steps timed
  double seconds_per_step = 0;  ///< wall time per step of this model [s]
  double rss_bytes = 0;         ///< peak resident memory after building mesh and engine [B]
  int threads = 1;
  /// CPU time over wall time x threads while the steps were timed: near 1
  /// on a machine to itself, well below when other work shares its cores.
  double cpu_share = 1;
  /// The machine's 1-minute load average after the probe (-1: unknown) and
  /// its cores: threads that spin while waiting keep cpu_share near 1 on a
  /// busy machine, the load average still names the other work.
  double load_average = -1;
  int cores = 0;
};

/// The note check prints beside its run-time figures when the probe got
/// less than half of its threads' time, or other work kept more than half
/// the machine's cores busy (the load average less the probe's threads):
/// a busy machine reads slow steps. Empty otherwise.
std::string busy_machine_note(const Probe& p);

/// Most triangles (by check's estimate) for which the probe runs: above,
/// meshing and engine alone take tens of seconds and gigabytes, and check
/// falls back to its documented constants.
inline constexpr double kProbeTriangleLimit = 400000;

/// Builds the scene's mesh and its engine at the hand-off (tunnels: the
/// in-situ stress left out, the core at the last alpha; specimens: between
/// their platens) on ctx.threads threads, and times `steps` steps.
/// Throws what meshing or the engine throws for bad input.
Probe probe_scene(const Scene& scene, const RunContext& ctx);

}  // namespace rockfdem::workflows
