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
    : cli_(cli), free_(std::move(free)), targets_(std::move(targets)) {}

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

double CalibrationProblem::objective(const VariantResult& r) const {
  if (r.status == "failed" || r.status == "refused") return kFailedObjective;
  double f = 0;
  for (const Target& t : targets_) {
    const double s = figure(r, t);
    if (!std::isfinite(s)) return kFailedObjective;
    f += t.weight * std::pow((s - t.value) / t.value, 2);
  }
  return met_its_criteria(r) ? f : kNotAtEquilibriumObjective + f;
}

std::vector<Evaluation> CalibrationProblem::run_batch(
    const std::vector<std::vector<double>>& points) {
  std::vector<Variant> variants;
  for (const auto& x : points) variants.push_back(variant(x));
  const std::vector<std::string> texts = farm(variants.size(), [&](std::size_t i) {
    return run_variant(cli_, variants[i]).to_json().dump();
  });
  std::vector<Evaluation> done;
  for (std::size_t i = 0; i < texts.size(); ++i) {
    Evaluation e{points[i], variants[i], VariantResult::from_json(nlohmann::json::parse(texts[i])),
                 0};
    e.objective = objective(e.result);
    done.push_back(e);
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
