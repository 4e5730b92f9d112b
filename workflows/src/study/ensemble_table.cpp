#include "study/ensemble_table.hpp"

#include <map>

#include "study/study_table.hpp"

namespace rockfdem::workflows::study {
namespace {

constexpr const char* kSeedSuffix = "heterogeneity_seed";

// The settings of the keys that are not seeds: what names a group.
std::vector<std::string> group_of(const std::vector<std::string>& keys, const Variant& v) {
  std::vector<std::string> group;
  for (std::size_t k = 0; k < keys.size(); ++k)
    if (!is_seed_key(keys[k])) group.push_back(v.settings[k].second);
  return group;
}

EnsembleRow row_of(const std::vector<std::string>& group, const std::string& figure,
                   const std::vector<const VariantResult*>& members) {
  EnsembleRow row{group, figure, members.size(), 0, 0, {}};
  std::vector<double> values;
  for (const VariantResult* r : members) {
    if (r->status == "pending") {
      ++row.pending;
    } else if (r->status != "completed") {
      ++row.excluded;
    } else if (const auto f = r->figures.find(figure); f != r->figures.end() && f->is_number()) {
      values.push_back(f->get<double>());
    }
  }
  row.stats = describe_sample(values);
  return row;
}

}  // namespace

bool is_seed_key(const std::string& key) {
  const std::string suffix = kSeedSuffix;
  return key == suffix || (key.size() > suffix.size() &&
                           key.compare(key.size() - suffix.size(), suffix.size(), suffix) == 0 &&
                           key[key.size() - suffix.size() - 1] == '.');
}

std::vector<EnsembleRow> ensemble_rows(const std::vector<std::string>& keys,
                                       const std::vector<Variant>& variants,
                                       const std::vector<VariantResult>& results,
                                       const std::vector<std::string>& figures) {
  std::vector<std::vector<std::string>> order;
  std::map<std::vector<std::string>, std::vector<const VariantResult*>> members;
  for (std::size_t i = 0; i < variants.size(); ++i) {
    const std::vector<std::string> group = group_of(keys, variants[i]);
    if (!members.count(group)) order.push_back(group);
    members[group].push_back(&results[i]);
  }
  std::vector<EnsembleRow> rows;
  for (const auto& group : order)
    for (const std::string& figure : figures) rows.push_back(row_of(group, figure, members[group]));
  return rows;
}

std::vector<std::string> ensemble_figures(const std::vector<std::string>& figure_columns) {
  std::vector<std::string> f;
  for (const std::string& c : figure_columns)
    if (c != "state_hash" && c != "support_verdict") f.push_back(c);  // not numbers
  return f;
}

void write_ensemble_table(const std::string& path, const std::vector<std::string>& keys,
                          const std::vector<EnsembleRow>& rows) {
  std::vector<std::string> columns;
  for (const std::string& k : keys)
    if (!is_seed_key(k)) columns.push_back(k);
  columns.insert(columns.end(), {"figure", "realisations", "n", "excluded", "pending", "mean",
                                 "std", "ci95_low", "ci95_high", "min", "max"});
  Table table(columns);
  for (const EnsembleRow& r : rows) {
    std::vector<nlohmann::json> cells(r.group.begin(), r.group.end());
    cells.insert(cells.end(), {r.figure, r.realisations, r.stats.n, r.excluded, r.pending});
    for (double v :
         {r.stats.mean, r.stats.std, r.stats.ci95_low, r.stats.ci95_high, r.stats.min, r.stats.max})
      cells.push_back(number_or_empty(v));
    table.add(cells);
  }
  table.write(path);
}

}  // namespace rockfdem::workflows::study
