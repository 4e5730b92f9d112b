// Private: one function per subcommand, each taking a validated scene.
#pragma once

#include "rockfdem/workflows/cli.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

int command_check(const Scene& scene, const CommandLine& cli);
int command_mesh(const Scene& scene, const CommandLine& cli);
int command_insitu(const Scene& scene, const CommandLine& cli);
int command_run(const Scene& scene, const CommandLine& cli);
int run_tunnel(const Scene& scene, const CommandLine& cli);

/// The OpenMP thread count in force (after gmsh, which resets it).
int active_threads();

}  // namespace rockfdem::workflows
