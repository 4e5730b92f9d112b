#include "study/calibrate_report.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "record/output_dir.hpp"
#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/printable.hpp"
#include "study/study_inputs.hpp"
#include "study/study_ranks.hpp"
#include "study/study_table.hpp"

namespace fs = std::filesystem;

namespace rockfdem::workflows::study {
namespace {

std::size_t sensitivity_runs(const CalibrationProblem& p) { return 2 * p.free().size(); }

std::string unit_of(const Target& t) { return t.column.substr(t.column.rfind('_') + 1); }

// The fitted scene as TOML: the input with the fitted values set; a
// relative mesh file is made absolute, since the file moves to OUTDIR.
std::string best_scene_text(const CommandLine& cli, const Evaluation& best) {
  const Scene scene = scene_with(cli, best.variant.overrides(), "--free", best.variant.name);
  toml::table root = toml::parse(scene.canonical);
  if (auto* file = root.at_path("msh.file").as_string()) {
    const fs::path base = fs::absolute(cli.scene).parent_path();
    if (fs::path(file->get()).is_relative())
      *file = (base / file->get()).lexically_normal().string();
  }
  std::ostringstream out;
  out << "# " << printable(scene.title.empty() ? cli.scene : scene.title)
      << ": fitted by `rockfdem calibrate " << cli.scene << "`\n# set:";
  for (const std::string& o : best.variant.overrides()) out << ' ' << o;
  out << "\n\n" << root << '\n';
  return out.str();
}

void plot_misfit(const CalibrationProblem& problem, const std::string& path) {
  plots::PlotSeries all{"each run", {}, {}}, best{"best so far", {}, {}};
  double lowest = INFINITY;
  for (std::size_t i = 0; i < problem.record().size(); ++i) {
    const double f = std::max(problem.record()[i].objective, 1e-300);
    lowest = std::min(lowest, f);
    all.x.push_back(double(i + 1));
    all.y.push_back(std::log10(f));
    best.x.push_back(double(i + 1));
    best.y.push_back(std::log10(lowest));
  }
  const std::string why =
      draw(path, "Calibration: misfit of each run", "run (evaluation number)",
           "log10 objective (weighted sum of squared relative misfits)", {all, best});
  if (!why.empty()) std::cerr << "rockfdem: calibration.png not drawn: " << why << '\n';
}

// The search's last improvement of the best-so-far objective: which run,
// how far it moved the scaled parameters (the largest share of a range)
// and by what share it lowered the objective. None before two improvements.
std::optional<nlohmann::json> last_improvement(const CalibrationProblem& problem) {
  const std::vector<Evaluation>& r = problem.record();
  const std::size_t n = r.size() - std::min(r.size(), sensitivity_runs(problem));
  std::size_t best = 0, before = 0;
  bool improved = false;
  for (std::size_t i = 1; i < n; ++i)
    if (r[i].objective < r[best].objective) {
      before = best;
      best = i;
      improved = true;
    }
  if (!improved) return std::nullopt;
  double step = 0;
  for (std::size_t k = 0; k < r[best].x.size(); ++k)
    step = std::max(step, std::abs(r[best].x[k] - r[before].x[k]));
  const double drop = (r[before].objective - r[best].objective) / r[before].objective;
  return nlohmann::json{{"run", best + 1}, {"step_of_range", step}, {"objective_drop", drop}};
}

// A search cut off by --max-evals says how far it was from converging.
std::string stop_with_distance(const std::string& stop, const std::optional<nlohmann::json>& last) {
  if (stop != stop_reason(nlopt::MAXEVAL_REACHED)) return stop;
  if (!last) return stop + ", not converged: no run improved on the first";
  char b[200];
  std::snprintf(b, sizeof b,
                ", not converged: the last improvement (run %d) moved the parameters by %.3g of "
                "their ranges (converged: below %.0e) and lowered the objective by %.3g%%",
                (*last)["run"].get<int>(), (*last)["step_of_range"].get<double>(), kXTolerance,
                100 * (*last)["objective_drop"].get<double>());
  return stop + b;
}

nlohmann::json summary_json(const CalibrationProblem& problem, const Evaluation& best,
                            const Sensitivity& sensitivity, const std::string& stop,
                            const CommandLine& cli, double wall_s) {
  const std::optional<nlohmann::json> last = last_improvement(problem);
  nlohmann::json j{{"scene", cli.scene},
                   {"method", cli.study.method},
                   {"stop_reason", stop_with_distance(stop, last)},
                   {"last_improvement", last ? *last : nlohmann::json()},
                   {"runs", problem.record().size()},
                   {"search_runs", problem.record().size() - sensitivity_runs(problem)},
                   {"max_evals", cli.study.max_evals},
                   {"ranks", n_ranks()},
                   {"threads_per_run", cli.threads},
                   {"wall_time_s", wall_s},
                   {"best_variant", best.variant.name},
                   {"best_status", best.result.status},
                   {"best_met_its_criteria", CalibrationProblem::met_its_criteria(best.result)},
                   {"objective", best.objective}};
  const std::vector<double> v = problem.values(best.x);
  for (std::size_t k = 0; k < v.size(); ++k)
    j["parameters"].push_back({{"key", problem.free()[k].key},
                               {"lo", problem.free()[k].lo},
                               {"hi", problem.free()[k].hi},
                               {"fitted", v[k]}});
  if (problem.realisations() > 0) {
    j["realisations"] = problem.realisations();
    j["best_realisations_used"] = best.n;
  }
  for (std::size_t i = 0; i < problem.targets().size(); ++i) {
    const Target& t = problem.targets()[i];
    const double s = CalibrationProblem::figure(best.result, t);
    j["targets"].push_back({{"name", t.name},
                            {"unit", unit_of(t)},
                            {"target", t.value},
                            {"weight", t.weight},
                            {"fitted", s},
                            {"relative_misfit", (s - t.value) / t.value}});
    if (problem.realisations() > 0)
      j["targets"].back()["fitted_std"] = number_or_empty(best.spread[i]);
  }
  for (const SensitivityEntry& e : sensitivity)
    j["sensitivity"].push_back({{"target", e.target},
                                {"key", e.key},
                                {"derivative_unit", e.unit},
                                {"derivative", e.derivative},
                                {"elasticity", e.elasticity}});
  return j;
}

void print_table(const nlohmann::json& j) {
  std::printf(
      "calibration: %s after %d runs (and %d for the sensitivity) on %d rank(s), "
      "objective %.3g\n",
      j["stop_reason"].get<std::string>().c_str(), j["search_runs"].get<int>(),
      j["runs"].get<int>() - j["search_runs"].get<int>(), j["ranks"].get<int>(),
      j["objective"].get<double>());
  if (j.contains("realisations"))
    std::printf("  each run is a point of %d realisations (heterogeneity seeds 1 to %d)\n",
                j["realisations"].get<int>(), j["realisations"].get<int>());
  if (!j["best_met_its_criteria"].get<bool>())
    std::printf(
        "  no run met its criteria: the best ended `%s`, so its figures are not equilibrium "
        "figures and the fit below is no answer\n",
        j["best_status"].get<std::string>().c_str());
  for (const auto& p : j["parameters"])
    std::printf("  fitted %-32s = %.6g  (bounds %.4g to %.4g)\n",
                p["key"].get<std::string>().c_str(), p["fitted"].get<double>(),
                p["lo"].get<double>(), p["hi"].get<double>());
  for (const auto& t : j["targets"]) {
    std::printf("  target %-22s %.6g %s, fitted %.6g %s (%+.3f%%)",
                t["name"].get<std::string>().c_str(), t["target"].get<double>(),
                t["unit"].get<std::string>().c_str(), t["fitted"].get<double>(),
                t["unit"].get<std::string>().c_str(), 100 * t["relative_misfit"].get<double>());
    if (t.contains("fitted_std") && t["fitted_std"].is_number())
      std::printf(", the mean of %d realisations, std %.3g %s",
                  j["best_realisations_used"].get<int>(), t["fitted_std"].get<double>(),
                  t["unit"].get<std::string>().c_str());
    std::printf("\n");
  }
  std::printf(
      "  sensitivity at the optimum (elasticity: %% change of the figure per %% change of the "
      "key):\n");
  for (const auto& e : j["sensitivity"])
    std::printf("    %-22s w.r.t. %-28s d/dp = %.4g %s, elasticity %.4g\n",
                e["target"].get<std::string>().c_str(), e["key"].get<std::string>().c_str(),
                e["derivative"].get<double>(), e["derivative_unit"].get<std::string>().c_str(),
                e["elasticity"].get<double>());
}

}  // namespace

std::string stop_reason(nlopt::result result) {
  switch (result) {
    case nlopt::XTOL_REACHED:
      return "converged (steps below 1e-6 of each range)";
    case nlopt::FTOL_REACHED:
      return "converged (objective change below tolerance)";
    case nlopt::STOPVAL_REACHED:
      return "objective below the stop value";
    case nlopt::MAXEVAL_REACHED:
      return "stopped at --max-evals";
    case nlopt::ROUNDOFF_LIMITED:
      return "stopped by round-off (no further progress possible)";
    case nlopt::FORCED_STOP:
      return "stopped";
    default:
      return "stopped (NLopt code " + std::to_string(int(result)) + ")";
  }
}

Evaluation best_evaluation(const std::vector<Evaluation>& record) {
  Evaluation best = record.front();
  for (const Evaluation& e : record)
    if (e.objective < best.objective) best = e;
  return best;
}

void write_calibration_table(const CalibrationProblem& problem, const std::string& path) {
  std::vector<std::string> columns{"run", "variant"};
  for (const FreeKey& f : problem.free()) columns.push_back(f.key);
  for (const Target& t : problem.targets()) columns.push_back(t.name + "_" + unit_of(t));
  const bool ensemble = problem.realisations() > 0;
  if (ensemble) {
    columns.push_back("n");
    for (const Target& t : problem.targets()) columns.push_back(t.name + "_std_" + unit_of(t));
  }
  columns.insert(columns.end(), {"objective", "status", "wall_time_s"});
  Table table(columns);
  for (std::size_t i = 0; i < problem.record().size(); ++i) {
    const Evaluation& e = problem.record()[i];
    std::vector<nlohmann::json> row{i + 1, e.variant.name};
    for (double v : problem.values(e.x)) row.push_back(v);
    for (const Target& t : problem.targets()) {
      const double s = CalibrationProblem::figure(e.result, t);
      row.push_back(number_or_empty(s));
    }
    if (ensemble) {
      row.push_back(e.n);
      for (double sd : e.spread) row.push_back(number_or_empty(sd));
    }
    row.insert(row.end(), {e.objective, e.result.status, e.result.wall_s});
    table.add(row);
  }
  fs::create_directories(fs::path(path).parent_path());
  table.write(path);
}

void write_calibration_outputs(const CalibrationProblem& problem, const Evaluation& best,
                               const Sensitivity& sensitivity, const std::string& stop,
                               const CommandLine& cli, double wall_s) {
  coupling::atomic_write_text(output_path(cli.output_dir, "best_scene.toml"),
                              best_scene_text(cli, best));
  const nlohmann::json j = summary_json(problem, best, sensitivity, stop, cli, wall_s);
  coupling::atomic_write_text(output_path(cli.output_dir, "calibration_summary.json"), j.dump(2));
  plot_misfit(problem, output_path(cli.output_dir, "calibration.png"));
  if (!cli.quiet) print_table(j);
}

}  // namespace rockfdem::workflows::study
