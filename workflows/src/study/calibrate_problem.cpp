#include "study/calibrate_problem.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "study/study_ranks.hpp"

namespace rockfdem::workflows::study {

CalibrationProblem::CalibrationProblem(const CommandLine& cli, std::vector<FreeKey> free,
                                       std::vector<Target> targets)
    : cli_(cli),
      free_(std::move(free)),
      targets_(std::move(targets)),
      seeds_(read_realisations(cli.study)) {}

std::vector<double> CalibrationProblem::values(const std::vector<double>& x) const {
  std::vector<double> v;
  for (std::size_t j = 0; j < free_.size(); ++j)
    v.push_back(free_[j].lo + std::clamp(x[j], 0.0, 1.0) * (free_[j].hi - free_[j].lo));
  return v;
}

Variant CalibrationProblem::variant(const std::vector<double>& x) const {
  std::vector<std::pair<std::string, std::string>> settings;
  const std::vector<double> v = values(x);
  for (std::size_t j = 0; j < free_.size(); ++j)
    settings.push_back({free_[j].key, exact_text(v[j])});
  return make_variant(std::move(settings));
}

std::vector<double> CalibrationProblem::start(const Scene& scene) const {
  const toml::table root = toml::parse(scene.canonical);
  std::vector<double> x;
  for (const FreeKey& f : free_) {
    const std::optional<double> v = root.at_path(f.key).value<double>();
    x.push_back(v && *v >= f.lo && *v <= f.hi ? (*v - f.lo) / (f.hi - f.lo) : 0.5);
  }
  return x;
}

double CalibrationProblem::figure(const VariantResult& r, const Target& target) {
  const auto it = r.figures.find(target.column);
  return it != r.figures.end() && it->is_number() ? it->get<double>()
                                                  : std::numeric_limits<double>::quiet_NaN();
}

bool CalibrationProblem::met_its_criteria(const VariantResult& r) {
  return r.status == "completed";
}

double CalibrationProblem::objective(const Realisations& m) const {
  if (m.n == 0) return kFailedObjective;  // every run failed or was refused
  double f = 0;
  for (const Target& t : targets_) {
    const double s = figure(m.result, t);
    if (!std::isfinite(s)) return kFailedObjective;
    f += t.weight * std::pow((s - t.value) / t.value, 2);
  }
  return met_its_criteria(m.result) ? f : kNotAtEquilibriumObjective + f;
}

std::vector<Variant> CalibrationProblem::runs_of(const Variant& v) const {
  return seeds_.values.empty() ? std::vector<Variant>{v} : crossed({v}, seeds_);
}

Evaluation CalibrationProblem::evaluation(const std::vector<double>& x,
                                          const std::vector<VariantResult>& runs) const {
  const Variant v = variant(x);
  const Realisations m = merge_realisations(v.name, runs);
  Evaluation e{x, v, m.result, objective(m), m.n, {}};
  for (const Target& t : targets_) {
    const auto s = m.stats.find(t.column);
    e.spread.push_back(s != m.stats.end() ? s->second.std
                                          : std::numeric_limits<double>::quiet_NaN());
  }
  return e;
}

std::vector<Evaluation> CalibrationProblem::run_batch(
    const std::vector<std::vector<double>>& points) {
  std::vector<Variant> variants;  // each point's runs, one after another
  for (const auto& x : points) {
    const std::vector<Variant> runs = runs_of(variant(x));
    variants.insert(variants.end(), runs.begin(), runs.end());
  }
  const std::vector<std::string> texts = farm(variants.size(), [&](std::size_t i) {
    return run_variant(cli_, variants[i]).to_json().dump();
  });
  const std::size_t per_point = std::max<std::size_t>(1, realisations());
  std::vector<Evaluation> done;  // rank 0 only: the others have no texts
  for (std::size_t p = 0; p * per_point < texts.size(); ++p) {
    std::vector<VariantResult> runs;
    for (std::size_t i = p * per_point; i < (p + 1) * per_point; ++i)
      runs.push_back(VariantResult::from_json(nlohmann::json::parse(texts[i])));
    done.push_back(evaluation(points[p], runs));
  }
  return done;
}

std::vector<Evaluation> CalibrationProblem::evaluate(
    const std::vector<std::vector<double>>& points) {
  broadcast(nlohmann::json(points).dump());
  std::vector<Evaluation> done = run_batch(points);
  record_.insert(record_.end(), done.begin(), done.end());
  return done;
}

void CalibrationProblem::serve() {
  for (;;) {
    const nlohmann::json batch = nlohmann::json::parse(broadcast(""));
    if (batch.is_null()) return;
    run_batch(batch.get<std::vector<std::vector<double>>>());
  }
}

void CalibrationProblem::finish() {
  if (n_ranks() > 1) broadcast("null");
}

}  // namespace rockfdem::workflows::study
