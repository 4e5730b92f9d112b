// What `rockfdem calibrate` leaves in its output folder: calibration.csv
// (every run), best_scene.toml, calibration.png and calibration_summary.json,
// and the table of fitted values and sensitivities on the console.
#pragma once

#include <nlopt.hpp>
#include <string>
#include <vector>

#include "study/calibrate_problem.hpp"

namespace rockfdem::workflows::study {

/// d(figure)/d(parameter) at the optimum, by finite differences, and the
/// elasticity (p / s) ds/dp: the relative change of the figure per
/// relative change of the parameter.
struct SensitivityEntry {
  std::string target, key;
  std::string unit;  ///< of the derivative: the figure's unit per the key's
  double derivative = 0, elasticity = 0;
};
using Sensitivity = std::vector<SensitivityEntry>;

/// The search stops when its steps fall below this share of each scaled range.
constexpr double kXTolerance = 1e-6;

std::string stop_reason(nlopt::result result);

/// The evaluation with the lowest objective (the first of equals).
Evaluation best_evaluation(const std::vector<Evaluation>& record);

void write_calibration_table(const CalibrationProblem& problem, const std::string& path);

void write_calibration_outputs(const CalibrationProblem& problem, const Evaluation& best,
                               const Sensitivity& sensitivity, const std::string& stop,
                               const CommandLine& cli, double wall_s);

}  // namespace rockfdem::workflows::study
