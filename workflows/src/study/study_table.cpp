#include "study/study_table.hpp"

#include <cmath>
#include <stdexcept>

#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/printable.hpp"
#include "study/study_variants.hpp"

namespace rockfdem::workflows::study {
namespace {

std::string quoted(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string cell(const nlohmann::json& v) {
  if (v.is_null()) return "";
  if (v.is_number_integer()) return std::to_string(v.get<long long>());
  if (v.is_number()) return exact_text(v.get<double>());
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  // Messages may quote a scene's text: control characters as escapes, one
  // line per row.
  return quoted(printable(v.is_string() ? v.get<std::string>() : v.dump()));
}

std::string line(const std::vector<nlohmann::json>& cells) {
  std::string s;
  for (std::size_t i = 0; i < cells.size(); ++i) s += (i ? "," : "") + cell(cells[i]);
  return s + "\n";
}

}  // namespace

Table::Table(std::vector<std::string> columns) : n_columns_(columns.size()) {
  text_ = line(std::vector<nlohmann::json>(columns.begin(), columns.end()));
}

void Table::add(const std::vector<nlohmann::json>& row) {
  if (row.size() != n_columns_) throw std::logic_error("study table: row of the wrong width");
  text_ += line(row);
}

void Table::write(const std::string& path) const { coupling::atomic_write_text(path, text_); }

nlohmann::json number_or_empty(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

std::string draw(const std::string& path, const std::string& title, const std::string& x_label,
                 const std::string& y_label, const std::vector<plots::PlotSeries>& series) {
  std::string why;
  if (series.empty()) return "no finished variant has the figure";
  if (!plots::plot_xy_png(title, x_label, y_label, series, path, 900, 600, &why)) return why;
  return "";
}

}  // namespace rockfdem::workflows::study
