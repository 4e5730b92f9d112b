#include "commands/study_options.hpp"

#include "rockfdem/error.hpp"

namespace po = boost::program_options;

namespace rockfdem::workflows {
namespace {

using Strings = std::vector<std::string>;

// Which commands each study option belongs to.
const std::pair<const char*, const char*> kOwners[] = {
    {"vary", "sweep"},          {"samples", "sweep"},    {"realisations", "sweep"},
    {"target", "calibrate"},    {"weight", "calibrate"}, {"free", "calibrate"},
    {"max-evals", "calibrate"}, {"method", "calibrate"}, {"realisations", "calibrate"}};

// "`rockfdem sweep`" or "`rockfdem sweep` or `rockfdem calibrate`"; empty
// where `command` is one of them.
std::string owners_unless(const std::string& option, const std::string& command) {
  std::string owners;
  for (const auto& [o, owner] : kOwners) {
    if (option != o) continue;
    if (command == owner) return "";
    owners += (owners.empty() ? "`rockfdem " : " or `rockfdem ") + std::string(owner) + "`";
  }
  return owners;
}

}  // namespace

po::options_description study_options() {
  po::options_description o("Studies (sweep, calibrate)");
  o.add_options()("vary", po::value<Strings>()->composing(),
                  "sweep: KEY=V1,V2,... (the product of the lists) or KEY=LO:HI "
                  "(with --samples; repeatable)")(
      "samples", po::value<long>(), "sweep: N Latin hypercube samples over the KEY=LO:HI ranges")(
      "target", po::value<Strings>()->composing(),
      "calibrate: NAME=VALUE (repeatable). Tunnels [mm]: vault, left_shoulder, "
      "right_shoulder, left_wall, right_wall, invert (radial from the in-situ state), each "
      "with _since_support (since the support's installation), shoulders and walls (a pair's "
      "mean), left_shoulder_horizontal, right_shoulder_horizontal and their mean "
      "shoulders_horizontal (horizontal convergence, as monitoring reads it), "
      "vault_settlement, wall_chord_convergence, shoulder_chord_convergence. "
      "Specimens: peak_stress [MPa] (UCS, Brazilian), tensile_strength [MPa] (Brazilian), "
      "modulus [GPa] (UCS: the pre-peak modulus, the slope over 0.2-0.6 of the peak)")(
      "weight", po::value<Strings>()->composing(), "calibrate: NAME=W, a target's weight (1)")(
      "free", po::value<Strings>()->composing(),
      "calibrate: KEY=LO:HI, a scene number to fit within its bounds (repeatable)")(
      "max-evals", po::value<long>(), "calibrate: at most N runs for the optimiser (60)")(
      "method", po::value<std::string>(), "calibrate: bobyqa (default) or cobyla")(
      "realisations", po::value<long>(),
      "sweep, calibrate: N >= 2 runs per variant (per point), seeds "
      "materials.rock.heterogeneity_seed=1..N of a heterogeneous rock; sweep: ensemble.csv "
      "(each figure's mean, std, 95% interval); calibrate: fits the mean");
  return o;
}

void read_study_options(const po::variables_map& vm, CommandLine& cli) {
  for (const auto& [option, owner] : kOwners)
    if (const std::string owners = owners_unless(option, cli.command);
        vm.count(option) && !owners.empty())
      throw InputError(std::string("command line: --") + option + " belongs to " + owners);
  StudyOptions& s = cli.study;
  if (vm.count("vary")) s.vary = vm["vary"].as<Strings>();
  if (vm.count("samples")) s.samples = vm["samples"].as<long>();
  if (vm.count("target")) s.targets = vm["target"].as<Strings>();
  if (vm.count("weight")) s.weights = vm["weight"].as<Strings>();
  if (vm.count("free")) s.free = vm["free"].as<Strings>();
  if (vm.count("max-evals")) s.max_evals = vm["max-evals"].as<long>();
  if (vm.count("method")) s.method = vm["method"].as<std::string>();
  if (vm.count("realisations")) s.realisations = vm["realisations"].as<long>();
}

}  // namespace rockfdem::workflows
