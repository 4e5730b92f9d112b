// Private: one function per subcommand, each taking a validated scene.
#pragma once

#include "record/run_context.hpp"
#include "rockfdem/workflows/cli.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

int command_check(const Scene& scene, const RunContext& ctx);
int command_mesh(const Scene& scene, const RunContext& ctx);
int command_insitu(const Scene& scene, const RunContext& ctx);
int command_run(const Scene& scene, const RunContext& ctx);

/// Throws InputError (naming mesh.size_near) when the scene's estimated peak
/// memory exceeds this machine's physical memory; runs before meshing.
void refuse_if_too_large(const Scene& scene);

/// Commands living in other libraries (sweep, calibrate: MPI and NLopt
/// stay out of this one) sign up here before the command line runs; they
/// make a RunContext for each run they start.
using Command = int (*)(const Scene& scene, const CommandLine& cli);
void register_command(const std::string& name, Command command);

}  // namespace rockfdem::workflows
