#include "study/realisations.hpp"

namespace rockfdem::workflows::study {
namespace {

// The runs whose figures count (Realisations::n).
std::vector<const VariantResult*> figures_from(const std::vector<VariantResult>& runs) {
  std::vector<const VariantResult*> used;
  for (const VariantResult& r : runs)
    if (r.status == "completed") used.push_back(&r);
  if (!used.empty()) return used;
  for (const VariantResult& r : runs)
    if (r.status == "unstable" || r.status == "not_at_equilibrium") used.push_back(&r);
  return used;
}

}  // namespace

Realisations merge_realisations(const std::string& name, const std::vector<VariantResult>& runs) {
  Realisations m;
  const std::vector<const VariantResult*> used = figures_from(runs);
  m.n = used.size();
  std::map<std::string, std::vector<double>> values;
  for (const VariantResult* r : used)
    for (const auto& f : r->figures.items())
      if (f.value().is_number()) values[f.key()].push_back(f.value().get<double>());
  for (const auto& [column, v] : values) m.stats[column] = describe_sample(v);
  if (runs.size() == 1) {
    m.result = runs.front();
    return m;
  }
  m.result = VariantResult{name, "completed", "", 0, true, nlohmann::json::object()};
  for (const VariantResult& r : runs) {
    m.result.wall_s += r.wall_s;
    m.result.reused = m.result.reused && r.reused;
    if (r.status != "completed" && m.result.status == "completed") {
      m.result.status = r.status;
      m.result.message = "realisation " + r.name + ": " + r.message;
    }
  }
  for (const auto& [column, s] : m.stats) m.result.figures[column] = s.mean;
  return m;
}

}  // namespace rockfdem::workflows::study
