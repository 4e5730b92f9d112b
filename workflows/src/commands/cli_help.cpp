#include "commands/cli_help.hpp"

#include <sstream>
#include <vector>

namespace po = boost::program_options;

namespace rockfdem::workflows {
namespace {

struct CommandHelp {
  const char* name;
  const char* synopsis;
  const char* text;
  std::vector<const char*> options;  ///< long names, as in the global list
  const char* example;
};

const CommandHelp kCommands[] = {
    {"run",
     "rockfdem run [SCENE.toml | -] [options]",
     "Runs the whole sequence: mesh, implicit in-situ stage, explicit stages, outputs\n"
     "(summary.json, history.csv, ParaView frames, plots, scene.toml as run) in OUTDIR.\n"
     "Without a scene it runs the built-in default, the seed's horseshoe tunnel.",
     {"output", "threads", "set", "quiet", "force", "checkpoint-every", "restart", "force-dt"},
     "rockfdem run scenes/tunnel-seed.toml -o out/tunnel -j 2 --set stages[9].max_steps=2000"},
    {"check",
     "rockfdem check SCENE.toml | - [options]",
     "Validates the scene and prints derived figures (element counts, memory, time step,\n"
     "run-time bound); runs and writes nothing.",
     {"threads", "set"},
     "rockfdem check scenes/tunnel-seed.toml --set insitu.sigma_h=20e6"},
    {"mesh",
     "rockfdem mesh SCENE.toml | - [options]",
     "Meshes only: mesh.msh, mesh.vtu, preview.png (zones, bolts, key points) and\n"
     "summary.json in OUTDIR.",
     {"output", "threads", "set", "quiet", "force"},
     "rockfdem mesh scenes/tunnel-seed.toml -o out/mesh"},
    {"insitu",
     "rockfdem insitu SCENE.toml | - [options]",
     "Meshes and runs the implicit in-situ stage (one solve per insitu.alpha):\n"
     "insitu.vtu, insitu.pvd, insitu_vs_analytic.csv and summary.json in OUTDIR.",
     {"output", "threads", "set", "quiet", "force"},
     "rockfdem insitu scenes/kirsch-circular.toml -o out/insitu"},
    {"sweep",
     "[mpirun -np N] rockfdem sweep SCENE.toml --vary KEY=V1,V2,... [--vary ...] [options]",
     "Runs one variant per combination of the values (or --samples N Latin-hypercube\n"
     "points over --vary KEY=LO:HI ranges) in OUTDIR/variants/NAME, resuming finished\n"
     "ones; sweep.csv and sweep.png hold each variant's inputs and key figures.\n"
     "--realisations N runs each variant with heterogeneity seeds 1..N; ensemble.csv then\n"
     "holds each figure's n, mean, std, 95% interval of the mean (Student t), min and max\n"
     "over each group's completed realisations.",
     {"output", "threads", "set", "vary", "samples", "realisations"},
     "rockfdem sweep scenes/tunnel-seed.toml --vary materials.rock.young=5e9,1e10 -o out/sweep"},
    {"calibrate",
     "[mpirun -np N] rockfdem calibrate SCENE.toml --target NAME=VALUE --free KEY=LO:HI "
     "[options]",
     "Fits the --free keys to the targets (key-point mm, or a specimen's MPa) with NLopt's\n"
     "BOBYQA or COBYLA: calibration.csv, best_scene.toml, calibration.png and\n"
     "calibration_summary.json (fitted values, sensitivities) in OUTDIR.\n"
     "--realisations N runs each point with heterogeneity seeds 1..N and fits the\n"
     "targets' means over the completed realisations.",
     {"output", "threads", "set", "target", "weight", "free", "max-evals", "method",
      "realisations"},
     "rockfdem calibrate scenes/brazilian-disc.toml --target tensile_strength=5 "
     "--free materials.rock.tensile_strength=2e6:6e6 -j 2"},
};

}  // namespace

std::string subcommand_help(const std::string& command, const po::options_description& options) {
  for (const CommandHelp& c : kCommands) {
    if (command != c.name) continue;
    po::options_description own(std::string("Options of `rockfdem ") + c.name + "`");
    for (const char* name : c.options)
      for (const auto& o : options.options())
        if (o->long_name() == name) own.add(o);
    std::ostringstream out;
    out << "Usage: " << c.synopsis << "\n\n"
        << c.text << "\nA scene of `-` is read from stdin.\n\n"
        << own << "\nExample:\n  " << c.example << '\n';
    return out.str();
  }
  return {};
}

}  // namespace rockfdem::workflows
