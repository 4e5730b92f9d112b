// `rockfdem sweep SCENE --vary KEY=V1,V2,... [--vary ...] -o DIR`: one run
// per variant (the product of the lists, or --samples N Latin hypercube
// points over KEY=LO:HI ranges) in DIR/variants/<name>/, then DIR/sweep.csv
// (inputs, status and key figures per variant; rewritten after every
// finished variant), DIR/ensemble.csv where a heterogeneity seed is varied
// (--realisations N: seeds 1..N of each variant) and DIR/sweep.png. DIR is
// locked against a second study. Under
// mpirun the variants are spread over the ranks; the table is the same for
// any rank count.
#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <map>
#include <optional>

#include "record/output_dir.hpp"
#include "rockfdem/error.hpp"
#include "run/interrupt.hpp"
#include "study/ensemble_table.hpp"
#include "study/study_commands.hpp"
#include "study/study_figures.hpp"
#include "study/study_ranks.hpp"
#include "study/study_run.hpp"
#include "study/study_table.hpp"

namespace rockfdem::workflows::study {
namespace {

constexpr std::size_t kMostVariants = 100000;
constexpr std::size_t kMostSeries = 12;

constexpr const char* kPending = "pending";

// The product of the lists, or the Latin hypercube points over the ranges,
// each once per seed of --realisations (a list after the ranges).
std::vector<Variant> all_variants(const CommandLine& cli, const std::vector<VariedKey>& keys) {
  if (cli.study.samples == 0) return product_variants(keys);
  const bool seeds = !keys.back().range;
  const std::vector<Variant> points = latin_hypercube(
      std::vector<VariedKey>(keys.begin(), keys.end() - (seeds ? 1 : 0)), cli.study.samples);
  return seeds ? crossed(points, keys.back()) : points;
}

// Every variant's scene is checked before anything runs or is written;
// `ids` receives each variant's identity (study_run.hpp).
std::vector<Variant> checked_variants(const CommandLine& cli, const std::vector<VariedKey>& keys,
                                      std::vector<nlohmann::json>* ids) {
  std::size_t n = cli.study.samples > 0 ? std::size_t(cli.study.samples) : 1;
  for (const VariedKey& k : keys) {
    if (k.range) {
      scene_with(cli, {k.key + "=" + exact_text(k.lo)}, "--vary", k.key + "=" + exact_text(k.lo));
      scene_with(cli, {k.key + "=" + exact_text(k.hi)}, "--vary", k.key + "=" + exact_text(k.hi));
      continue;
    }
    for (const std::string& v : k.values)
      scene_with(cli, {k.key + "=" + v}, "--vary", k.key + "=" + v);
    n *= k.values.size();
    if (n > kMostVariants)
      throw InputError("command line: --vary: the product of the lists holds over " +
                       std::to_string(kMostVariants) + " variants; allowed: fewer values");
  }
  std::vector<Variant> variants = all_variants(cli, keys);
  bool heterogeneous = false;
  for (const Variant& v : variants) {
    stop_study_if_interrupted(cli, "while checking the variants' scenes (nothing run)");
    const Scene scene = scene_with(cli, v.overrides(), "--vary", v.name);
    heterogeneous = heterogeneous || heterogeneous_rock(scene);
    ids->push_back(variant_identity(scene, v));
  }
  check_realisations_differ(cli.study, heterogeneous);
  return variants;
}

bool varies_a_seed(const std::vector<VariedKey>& keys) {
  return std::any_of(keys.begin(), keys.end(),
                     [](const VariedKey& k) { return is_seed_key(k.key); });
}

// sweep.csv, and ensemble.csv where a seed is varied.
void write_tables(const std::string& dir, const Scene& scene, const std::vector<VariedKey>& keys,
                  const std::vector<Variant>& variants, const std::vector<VariantResult>& results) {
  std::vector<std::string> columns{"variant"};
  for (const VariedKey& k : keys) columns.push_back(k.key);
  columns.push_back("status");
  const std::vector<std::string> figures = figure_columns(scene);
  columns.insert(columns.end(), figures.begin(), figures.end());
  columns.insert(columns.end(), {"status_reason", "wall_time_s"});
  Table table(columns);
  for (std::size_t i = 0; i < variants.size(); ++i) {
    std::vector<nlohmann::json> row{variants[i].name};
    for (const auto& setting : variants[i].settings) row.push_back(setting.second);
    row.push_back(results[i].status);
    for (const std::string& c : figures)
      row.push_back(results[i].figures.value(c, nlohmann::json()));
    row.push_back(results[i].message);
    row.push_back(results[i].status == kPending ? nlohmann::json()
                                                : nlohmann::json(results[i].wall_s));
    table.add(row);
  }
  table.write(output_path(dir, "sweep.csv"));
  if (!varies_a_seed(keys)) return;
  std::vector<std::string> names;
  for (const VariedKey& k : keys) names.push_back(k.key);
  write_ensemble_table(output_path(dir, "ensemble.csv"), names,
                       ensemble_rows(names, variants, results, ensemble_figures(figures)));
}

// The study so far: what this rank has run, else what the variants' folders
// record as finished (run by another rank or an earlier study), else pending.
std::vector<VariantResult> so_far(const CommandLine& cli, const std::vector<Variant>& variants,
                                  const std::vector<nlohmann::json>& ids,
                                  const std::vector<std::optional<VariantResult>>& mine) {
  std::vector<VariantResult> results;
  for (std::size_t i = 0; i < variants.size(); ++i) {
    std::optional<VariantResult> r = mine[i] ? mine[i] : recorded_result(cli, variants[i], ids[i]);
    if (!r) r = VariantResult{variants[i].name, kPending, "", 0, false, nlohmann::json::object()};
    results.push_back(*r);
  }
  return results;
}

// Runs the variants; the tables are rewritten after each, whichever rank ran it.
std::vector<VariantResult> run_all(const CommandLine& cli, const Scene& scene,
                                   const std::vector<VariedKey>& keys,
                                   const std::vector<Variant>& variants,
                                   const std::vector<nlohmann::json>& ids) {
  std::vector<std::optional<VariantResult>> mine(variants.size());
  const std::vector<std::string> texts = farm(variants.size(), [&](std::size_t i) {
    mine[i] = run_variant(cli, variants[i]);
    write_tables(cli.output_dir, scene, keys, variants, so_far(cli, variants, ids, mine));
    return mine[i]->to_json().dump();
  });
  std::vector<VariantResult> results;
  for (const std::string& t : texts)
    results.push_back(VariantResult::from_json(nlohmann::json::parse(t)));
  return results;
}

// x of a variant: its first key's value, or the value's place in the list
// when the values are not all numbers.
std::vector<double> abscissae(const VariedKey& first, const std::vector<Variant>& variants,
                              std::string* label) {
  std::vector<double> x;
  bool numbers = true;
  for (const Variant& v : variants) {
    char* end = nullptr;
    const std::string& text = v.settings.front().second;
    x.push_back(std::strtod(text.c_str(), &end));
    numbers = numbers && end == text.c_str() + text.size();
  }
  *label = first.key;
  if (numbers) return x;
  *label = "place of " + first.key + " in its --vary list";
  for (std::size_t i = 0; i < variants.size(); ++i)
    x[i] = double(
        std::find(first.values.begin(), first.values.end(), variants[i].settings.front().second) -
        first.values.begin());
  return x;
}

// One curve per combination of the other keys (all in one, sorted by x,
// where those are too many: a Latin hypercube).
std::vector<plots::PlotSeries> curves(const std::vector<Variant>& variants,
                                      const std::vector<VariantResult>& results,
                                      const std::vector<double>& x, const std::string& column) {
  std::map<std::string, plots::PlotSeries> groups;
  std::vector<std::size_t> order(variants.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  for (std::size_t i : order) {
    std::string name;
    for (std::size_t k = 1; k < variants[i].settings.size(); ++k)
      name += (k > 1 ? ", " : "") + variants[i].settings[k].first + "=" +
              variants[i].settings[k].second;
    const nlohmann::json& y = results[i].figures.value(column, nlohmann::json());
    if (!y.is_number()) continue;
    plots::PlotSeries& s = groups[name.empty() ? column : name];
    s.name = name.empty() ? column : name;
    s.x.push_back(x[i]);
    s.y.push_back(y.get<double>());
  }
  std::vector<plots::PlotSeries> series;
  for (auto& [name, s] : groups) series.push_back(s);
  // Runs that stopped short of their criteria: marked where they lie.
  plots::PlotSeries short_of{"not completed (unstable, not at equilibrium, ...)", {}, {}, true};
  for (std::size_t i : order)
    if (results[i].status != "completed" && results[i].status != kPending &&
        results[i].figures.value(column, nlohmann::json()).is_number()) {
      short_of.x.push_back(x[i]);
      short_of.y.push_back(results[i].figures[column].get<double>());
    }
  if (!short_of.x.empty()) series.push_back(short_of);
  if (series.size() <= kMostSeries) return series;
  plots::PlotSeries all{column + " (all variants)", {}, {}};
  for (std::size_t i : order)
    if (results[i].figures.value(column, nlohmann::json()).is_number()) {
      all.x.push_back(x[i]);
      all.y.push_back(results[i].figures[column].get<double>());
    }
  if (short_of.x.empty()) return {all};
  return {all, short_of};
}

void plot_sweep(const std::string& path, const Scene& scene, const std::vector<VariedKey>& keys,
                const std::vector<Variant>& variants, const std::vector<VariantResult>& results) {
  const std::string column = figure_columns(scene).front();  // vault radial, or peak stress
  std::string x_label;
  const std::vector<double> x = abscissae(keys.front(), variants, &x_label);
  const bool tunnel = column != "peak_stress_MPa";
  const std::string why = draw(
      path, tunnel ? "Vault: radial displacement at the end of each run" : "Specimen peak stress",
      x_label, tunnel ? "vault radial displacement [mm]" : "peak stress [MPa]",
      curves(variants, results, x, column));
  if (!why.empty()) std::cerr << "rockfdem: sweep.png not drawn: " << why << '\n';
}

void report(const std::vector<VariantResult>& results, const std::string& dir, bool ensemble) {
  std::size_t reused = 0, failed = 0;
  for (const VariantResult& r : results) {
    reused += r.reused;
    if (r.status == "failed" || r.status == "refused") {
      ++failed;
      std::cout << "variant " << r.name << ": " << r.status << ": " << r.message << '\n';
    }
  }
  std::cout << "sweep: " << results.size() << " variants on " << n_ranks()
            << " rank(s): " << results.size() - reused << " run now, " << reused
            << " taken from earlier runs, " << failed << " failed or refused; table "
            << output_path(dir, "sweep.csv");
  if (ensemble)
    std::cout << ", ensemble statistics (mean, std, 95% interval of the mean) "
              << output_path(dir, "ensemble.csv");
  std::cout << '\n';
}

}  // namespace

int command_sweep(const Scene& scene, const CommandLine& cli) {
  install_interrupt_handlers();  // for the whole study: see stop_study_if_interrupted
  signal_point("study-start");
  const std::vector<VariedKey> keys = read_vary(cli.study);
  std::vector<nlohmann::json> ids;
  const std::vector<Variant> variants = checked_variants(cli, keys, &ids);
  if (rank() == 0) or_abort_all([&] { lock_study_dir(cli.output_dir); });
  const std::vector<VariantResult> results = run_all(cli, scene, keys, variants, ids);
  if (rank() != 0) return 0;
  write_tables(cli.output_dir, scene, keys, variants, results);
  if (scene.output.plots)
    plot_sweep(output_path(cli.output_dir, "sweep.png"), scene, keys, variants, results);
  report(results, cli.output_dir, varies_a_seed(keys));
  signal_point("study-end");
  stop_study_if_interrupted(cli, "as the sweep ended (its variants and table are written)");
  return 0;
}

}  // namespace rockfdem::workflows::study
