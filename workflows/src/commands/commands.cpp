// Dispatch: validate the whole scene first, whichever subcommand runs, then
// hand it to the subcommand.
#include "commands/commands.hpp"

#include <omp.h>

#include <iostream>
#include <map>

#include "rockfdem/error.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/workflows/cli.hpp"
#include "rockfdem/workflows/scene_schema.hpp"
#include "rockfdem/workflows/version.hpp"

namespace rockfdem::workflows {
namespace {
std::map<std::string, Command>& registered() {
  static std::map<std::string, Command> commands;
  return commands;
}
}  // namespace

void register_command(const std::string& name, Command command) { registered()[name] = command; }

int run_command(const CommandLine& cli) {
  if (cli.help) {
    std::cout << cli.help_text;
    return 0;
  }
  if (cli.version) {
    std::cout << "rockfdem " << version_string() << '\n';
    return 0;
  }
  if (cli.scene_reference) {
    std::cout << scene_reference_markdown();
    return 0;
  }
  const Scene scene =
      cli.scene.empty() ? load_default_scene(cli.overrides) : load_scene(cli.scene, cli.overrides);
  for (const std::string& w : scene.warnings) std::cerr << "rockfdem: warning: " << w << '\n';
  const RunContext ctx = run_context(cli);
  omp_set_num_threads(ctx.threads);  // gmsh reads its thread count from OpenMP's
  refuse_if_too_large(scene);
  fdem::check_environment();  // before anything is written
  if (cli.command == "check") return command_check(scene, ctx);
  if (cli.command == "mesh") return command_mesh(scene, ctx);
  if (cli.command == "insitu") return command_insitu(scene, ctx);
  if (cli.command != "run") {
    const auto found = registered().find(cli.command);
    if (found == registered().end())
      throw InputError("command line: `rockfdem " + cli.command + "` is not in this build");
    return found->second(scene, cli);
  }
  return command_run(scene, ctx);
}

}  // namespace rockfdem::workflows
