// history.csv: one row per output interval, written atomically after each
// row so an interrupted run keeps a valid history.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rockfdem::workflows {

class History {
 public:
  History(std::string path, std::vector<std::string> columns);
  /// Appends a row (as many values as columns) and rewrites the file; a
  /// NaN (no value at this step) is written "nan".
  void add(const std::vector<double>& row);
  const std::vector<std::vector<double>>& rows() const { return rows_; }
  /// Replaces the rows (a restarted run continues its checkpoint's history).
  void restore(const std::vector<std::vector<double>>& rows);
  /// Rows as a run state holds them (rows() in JSON, where NaN, no value,
  /// reads null) back to numbers.
  static std::vector<std::vector<double>> rows_from_json(const nlohmann::json& rows);
  /// The values of one column, for plots.
  std::vector<double> column(const std::string& name) const;
  const std::vector<std::string>& columns() const { return columns_; }

 private:
  void append_text(const std::vector<double>& row);
  std::string path_;
  std::vector<std::string> columns_;
  std::vector<std::vector<double>> rows_;
  std::string text_;
};

}  // namespace rockfdem::workflows
