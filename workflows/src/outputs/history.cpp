#include "outputs/history.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/error.hpp"

namespace rockfdem::workflows {

History::History(std::string path, std::vector<std::string> columns)
    : path_(std::move(path)), columns_(std::move(columns)) {
  for (std::size_t i = 0; i < columns_.size(); ++i) text_ += (i ? "," : "") + columns_[i];
  text_ += '\n';
}

void History::append_text(const std::vector<double>& row) {
  if (row.size() != columns_.size()) throw std::logic_error("history row has the wrong width");
  char buf[32];
  for (std::size_t i = 0; i < row.size(); ++i) {
    // NaN: no value at this step (the lining's columns before it is
    // installed), written "nan", which strtod, Python's float() and
    // NumPy's loadtxt read back as NaN (an empty cell they refuse).
    if (std::isnan(row[i]))
      std::snprintf(buf, sizeof buf, "nan");
    else
      std::snprintf(buf, sizeof buf, "%.10g", row[i]);
    text_ += (i ? "," : "") + std::string(buf);
  }
  text_ += '\n';
}

void History::add(const std::vector<double>& row) {
  append_text(row);
  rows_.push_back(row);
  coupling::atomic_write_text(path_, text_);
}

void History::restore(const std::vector<std::vector<double>>& rows) {
  for (const auto& r : rows)
    if (r.size() != columns_.size())
      throw InputError("corrupt run state: a history row has " + std::to_string(r.size()) +
                       " values; history.csv has " + std::to_string(columns_.size()) + " columns");
  text_.erase(text_.find('\n') + 1);  // keep the header
  for (const auto& r : rows) append_text(r);
  rows_ = rows;
  coupling::atomic_write_text(path_, text_);
}

std::vector<std::vector<double>> History::rows_from_json(const nlohmann::json& rows) {
  std::vector<std::vector<double>> out;
  for (const nlohmann::json& r : rows) {
    out.emplace_back();
    for (const nlohmann::json& v : r) out.back().push_back(v.is_null() ? NAN : v.get<double>());
  }
  return out;
}

std::vector<double> History::column(const std::string& name) const {
  std::size_t k = 0;
  while (k < columns_.size() && columns_[k] != name) ++k;
  if (k == columns_.size()) throw std::logic_error("no history column " + name);
  std::vector<double> out;
  for (const auto& r : rows_) out.push_back(r[k]);
  return out;
}

}  // namespace rockfdem::workflows
