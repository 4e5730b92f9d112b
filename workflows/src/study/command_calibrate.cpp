// `rockfdem calibrate SCENE --target NAME=VALUE ... --free KEY=LO:HI ...`:
// back-analysis. NLopt's BOBYQA (or COBYLA) moves the free keys, scaled to
// [0, 1], to minimise the weighted sum of squared relative misfits of the
// targets (calibrate_problem.hpp); with --realisations N, of the targets'
// means over N heterogeneity seeds per point. Both are sequential: one
// point per step (its realisations spread over the ranks), so under mpirun
// the other ranks otherwise wait during the search, and they share the
// sensitivity runs at the optimum.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <iostream>
#include <nlopt.hpp>

#include "record/output_dir.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/workflows/scene_schema.hpp"
#include "run/interrupt.hpp"
#include "scene/scene_reader.hpp"
#include "study/calibrate_problem.hpp"
#include "study/calibrate_report.hpp"
#include "study/study_commands.hpp"
#include "study/study_ranks.hpp"

namespace rockfdem::workflows::study {
namespace {

constexpr double kStartStep = 0.1;  // of each scaled range: the first trust region
constexpr double kSensitivityStep = 0.01;

nlopt::algorithm algorithm(const std::string& method) {
  if (method == "bobyqa") return nlopt::LN_BOBYQA;
  if (method == "cobyla") return nlopt::LN_COBYLA;
  throw InputError("command line: --method " + method + ": allowed: bobyqa, cobyla");
}

// The search, on rank 0. Exceptions in the objective (an interrupt) stop
// NLopt and are raised again here; NLopt would take them for its own failure.
std::string search(CalibrationProblem& problem, const CommandLine& cli, const Scene& scene) {
  nlopt::opt opt(algorithm(cli.study.method), unsigned(problem.free().size()));
  opt.set_lower_bounds(0.0);
  opt.set_upper_bounds(1.0);
  opt.set_maxeval(int(cli.study.max_evals));
  opt.set_xtol_abs(kXTolerance);
  opt.set_initial_step(kStartStep);
  std::exception_ptr failure;
  auto f = [&](const std::vector<double>& x) {
    try {
      const double value = problem.evaluate({x}).front().objective;
      write_calibration_table(problem, output_path(cli.output_dir, "calibration.csv"));
      return value;
    } catch (...) {
      failure = std::current_exception();
      opt.force_stop();
      return CalibrationProblem::kFailedObjective;
    }
  };
  using F = decltype(f);
  opt.set_min_objective([](const std::vector<double>& x, std::vector<double>&,
                           void* data) { return (*static_cast<F*>(data))(x); },
                        &f);
  std::vector<double> x = problem.start(scene);
  double best = 0;
  nlopt::result result = nlopt::FAILURE;
  try {
    result = opt.optimize(x, best);
  } catch (const nlopt::roundoff_limited&) {
    result = nlopt::ROUNDOFF_LIMITED;
  } catch (const nlopt::forced_stop&) {
    result = nlopt::FORCED_STOP;
  }
  if (failure) std::rethrow_exception(failure);
  return stop_reason(result);
}

// Finite differences at the optimum: x_j +- h (one-sided at a bound).
Sensitivity sensitivity(CalibrationProblem& problem, const Evaluation& best) {
  std::vector<std::vector<double>> points;
  Sensitivity s;
  for (std::size_t j = 0; j < best.x.size(); ++j) {
    std::vector<double> up = best.x, down = best.x;
    up[j] = std::min(1.0, best.x[j] + kSensitivityStep);
    down[j] = std::max(0.0, best.x[j] - kSensitivityStep);
    points.push_back(up);
    points.push_back(down);
  }
  const std::vector<Evaluation> runs = problem.evaluate(points);
  for (std::size_t j = 0; j < best.x.size(); ++j) {
    const FreeKey& k = problem.free()[j];
    const double dp = (runs[2 * j].x[j] - runs[2 * j + 1].x[j]) * (k.hi - k.lo);
    const double p = problem.values(best.x)[j];
    for (const Target& t : problem.targets()) {
      const double d = (CalibrationProblem::figure(runs[2 * j].result, t) -
                        CalibrationProblem::figure(runs[2 * j + 1].result, t)) /
                       dp;
      const KeySpec* spec = find_key(detail::normalise(k.key));
      const std::string unit = t.column.substr(t.column.rfind('_') + 1) + " per " +
                               (spec && spec->unit != "-" ? spec->unit : "unit");
      s.push_back({t.name, k.key, unit, d, d * p / CalibrationProblem::figure(best.result, t)});
    }
  }
  return s;
}

}  // namespace

int command_calibrate(const Scene& scene, const CommandLine& cli) {
  const auto start = std::chrono::steady_clock::now();
  install_interrupt_handlers();  // for the whole study: see stop_study_if_interrupted
  signal_point("study-start");
  algorithm(cli.study.method);
  if (cli.study.max_evals < 1 || cli.study.max_evals > 100000)
    throw InputError("command line: --max-evals " + std::to_string(cli.study.max_evals) +
                     ": allowed 1 to 100000");
  const std::vector<FreeKey> free = read_free(cli.study);
  for (const FreeKey& f : free) {
    scene_with(cli, {f.key + "=" + exact_text(f.lo)}, "--free", f.key + "=" + exact_text(f.lo));
    scene_with(cli, {f.key + "=" + exact_text(f.hi)}, "--free", f.key + "=" + exact_text(f.hi));
  }
  CalibrationProblem problem(cli, free, read_targets(cli.study, scene));
  check_realisations_differ(
      cli.study,
      heterogeneous_rock(scene) || std::any_of(free.begin(), free.end(), [](const FreeKey& f) {
        return f.key == "materials.rock.heterogeneity";
      }));
  stop_study_if_interrupted(cli, "while checking the free keys' scenes (nothing run)");
  if (rank() == 0) or_abort_all([&] { lock_study_dir(cli.output_dir); });
  if (rank() != 0) {
    problem.serve();
    return 0;
  }
  or_abort_all([&] {
    const std::string stop = search(problem, cli, scene);
    const Evaluation best = best_evaluation(problem.record());
    const Sensitivity s = sensitivity(problem, best);
    problem.finish();
    write_calibration_table(problem, output_path(cli.output_dir, "calibration.csv"));
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    write_calibration_outputs(problem, best, s, stop, cli, wall);
  });
  signal_point("study-end");
  stop_study_if_interrupted(cli, "as the calibration ended (its outputs are written)");
  return 0;
}

}  // namespace rockfdem::workflows::study
