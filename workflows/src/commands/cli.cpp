#include "rockfdem/workflows/cli.hpp"

#include <boost/program_options.hpp>
#include <charconv>
#include <cstdlib>
#include <sstream>

#include "commands/cli_help.hpp"
#include "commands/study_options.hpp"
#include "rockfdem/error.hpp"

namespace po = boost::program_options;

namespace rockfdem::workflows {
namespace {

const char* const kUsage =
    "Usage:\n"
    "  rockfdem run [SCENE.toml] [-o OUTDIR] [-j THREADS] [--set section.key=value ...] [-q]\n"
    "               [--checkpoint-every N] [--restart CHECKPOINT] [--force-dt] [--force]\n"
    "  rockfdem check SCENE.toml     validate, print derived figures, run nothing\n"
    "  rockfdem mesh SCENE.toml      mesh only (mesh.msh, mesh.vtu, preview.png, summary.json)\n"
    "  rockfdem insitu SCENE.toml    mesh + implicit in-situ stage\n"
    "  [mpirun -np N] rockfdem sweep SCENE.toml --vary KEY=V1,V2,... [--samples N]\n"
    "                 [--realisations N] [-o DIR]\n"
    "  [mpirun -np N] rockfdem calibrate SCENE.toml --target NAME=VALUE --free KEY=LO:HI\n"
    "                 [--realisations N] [-o DIR]\n"
    "  rockfdem COMMAND --help       help on one command: its options and an example\n"
    "  rockfdem --scene-reference    every scene key, its unit, default and range (Markdown)\n"
    "  rockfdem --help | --version\n\n"
    "Without a scene, `run` uses the built-in default: the seed's horseshoe tunnel.\n"
    "A scene of `-` is read from stdin.\n"
    "Exit codes: 0 success, 2 bad input, 3 numerical failure, 1 anything else.\n";

po::options_description visible_options() {
  po::options_description o("Options");
  o.add_options()("help,h", "print this help")("version", "print the version")(
      "output,o", po::value<std::string>()->default_value("rockfdem-out"), "output directory")(
      "threads,j", po::value<int>(),
      "OpenMP threads (0: all cores; without -j: OMP_NUM_THREADS if set, else all cores)")(
      "set", po::value<std::vector<std::string>>()->composing(),
      "override a scene key: --set section.key=value (repeatable)")("quiet,q",
                                                                    "no progress on stderr")(
      "force",
      "write into an output directory holding another run's results: the files rockfdem "
      "wrote there are removed first (others stay)")(
      "checkpoint-every", po::value<long>(),
      "write a checkpoint every N steps (at the next output step; keeps the newest two)")(
      "restart", po::value<std::string>(), "continue a run from a checkpoint file")(
      "force-dt", "accept an engine.dt above the stability limit (the run stops if it diverges)");
  return o;
}

// OMP_NUM_THREADS as the thread count when -j is not given; 0 (all cores)
// when it is unset or empty.
int threads_from_environment() {
  const char* value = std::getenv("OMP_NUM_THREADS");
  if (!value || !*value) return 0;
  const std::string text(value);
  int n = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (ec != std::errc() || end != text.data() + text.size() || n < 1 || n > 4096)
    throw InputError("environment: OMP_NUM_THREADS=" + text.substr(0, 40) +
                     ": not a thread count; allowed: a whole number from 1 to 4096 (or pass -j)");
  return n;
}

}  // namespace

CommandLine parse_command_line(int argc, const char* const argv[]) {
  po::options_description visible = visible_options();
  visible.add(study_options());
  po::options_description hidden;
  hidden.add_options()("command", po::value<std::string>(), "")("scene", po::value<std::string>(),
                                                                "")("scene-reference", "");
  po::options_description all;
  all.add(visible).add(hidden);
  po::positional_options_description positional;
  positional.add("command", 1).add("scene", 1);

  po::variables_map vm;
  try {
    po::store(po::command_line_parser(argc, argv).options(all).positional(positional).run(), vm);
    po::notify(vm);
  } catch (const po::error& e) {
    throw InputError(std::string("command line: ") + e.what() + "; see rockfdem --help");
  }
  CommandLine cli;
  if (vm.count("command")) cli.command = vm["command"].as<std::string>();
  cli.help_text = subcommand_help(cli.command, visible);
  if (cli.help_text.empty()) {
    std::ostringstream help;
    help << kUsage << '\n' << visible;
    cli.help_text = help.str();
  }
  cli.help = vm.count("help") > 0;
  cli.version = vm.count("version") > 0;
  cli.scene_reference = vm.count("scene-reference") > 0;
  cli.quiet = vm.count("quiet") > 0;
  cli.force = vm.count("force") > 0;
  cli.force_dt = vm.count("force-dt") > 0;
  if (vm.count("checkpoint-every")) cli.checkpoint_every = vm["checkpoint-every"].as<long>();
  if (vm.count("restart")) cli.restart = vm["restart"].as<std::string>();
  cli.output_dir = vm["output"].as<std::string>();
  if (vm.count("set")) cli.overrides = vm["set"].as<std::vector<std::string>>();
  if (vm.count("scene")) cli.scene = vm["scene"].as<std::string>();
  if (cli.help || cli.version || cli.scene_reference) return cli;
  cli.threads = vm.count("threads") ? vm["threads"].as<int>() : threads_from_environment();

  if (cli.command.empty()) throw InputError("command line: no command given; see rockfdem --help");
  if (cli.command != "run" && cli.command != "check" && cli.command != "mesh" &&
      cli.command != "insitu" && cli.command != "sweep" && cli.command != "calibrate")
    throw InputError("command line: unknown command '" + cli.command +
                     "'; allowed: run, check, mesh, insitu, sweep, calibrate");
  read_study_options(vm, cli);
  if (cli.scene.empty() && cli.command != "run")
    throw InputError("command line: `rockfdem " + cli.command + "` needs a scene file");
  if (cli.threads < 0 || cli.threads > 4096)
    throw InputError("command line: -j " + std::to_string(cli.threads) +
                     ": allowed 0 (all cores) to 4096");
  if (vm.count("checkpoint-every") && cli.checkpoint_every < 0)
    throw InputError("command line: --checkpoint-every " + std::to_string(cli.checkpoint_every) +
                     ": allowed 0 (none) or a positive step count");
  if ((!cli.restart.empty() || vm.count("checkpoint-every")) && cli.command != "run")
    throw InputError("command line: --restart and --checkpoint-every belong to `rockfdem run`");
  if (cli.output_dir.empty()) throw InputError("command line: -o needs a directory");
  return cli;
}

}  // namespace rockfdem::workflows
