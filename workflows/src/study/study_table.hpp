// CSV tables of a study (sweep.csv, calibration.csv), written atomically:
// a reader sees the previous complete table or the new one.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rockfdem/plots/plot.hpp"

namespace rockfdem::workflows::study {

class Table {
 public:
  explicit Table(std::vector<std::string> columns);
  /// Appends a row; each cell is a JSON value: numbers are written exactly
  /// (the shortest text that reads back as the same double), strings quoted
  /// where they hold a comma or quote, null as an empty cell.
  void add(const std::vector<nlohmann::json>& row);
  void write(const std::string& path) const;

 private:
  std::string text_;
  std::size_t n_columns_;
};

/// A cell for `v`: the number, or empty where it is not finite (a statistic
/// its sample does not define).
nlohmann::json number_or_empty(double v);

/// Draws a line plot to `path`; returns "" or why it was not drawn (no
/// display: run under xvfb-run).
std::string draw(const std::string& path, const std::string& title, const std::string& x_label,
                 const std::string& y_label, const std::vector<plots::PlotSeries>& series);

}  // namespace rockfdem::workflows::study
