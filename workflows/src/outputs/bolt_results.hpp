// What a tunnel run reports about its bolts, from their section forces
// (fdem/bolt_sections.hpp: the strip cut normal to its axis, N per bar):
// per output step the largest axial force per bolt (history.csv columns),
// the profiles (bolts.csv rows) and the bolts as polylines (bolts_NNNN.vtp
// in bolts.pvd); at the end each bolt's final profile (bolt_NN.csv), its
// summary entry and bolt_forces.png. docs/output-formats.md, "Bolts".
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "outputs/output_step.hpp"
#include "outputs/run_plots.hpp"
#include "record/summary.hpp"
#include "rockfdem/coupling/vtk_writer.hpp"
#include "rockfdem/fdem/bolt_sections.hpp"
#include "rockfdem/plots/plot.hpp"

namespace rockfdem::workflows {

class BoltResults : public OutputStepObserver {
 public:
  /// `is_cable` per bolt (kind in the outputs); files go to `dir`.
  BoltResults(const fdem::BoltPlan& plan, std::vector<std::uint8_t> is_cable, std::string dir);
  /// "bolt_NN_max_axial_kN" per bolt.
  std::vector<std::string> history_columns() const override;
  /// record()'s forces into the row.
  void at_output_step(const OutputStep& step, std::vector<double>& row) override;
  /// Takes this output step's profiles, appends them to bolts.csv
  /// (rewritten atomically) and returns each bolt's axial force of largest
  /// magnitude [kN per bar, tension positive]; 0 while not installed.
  std::vector<double> record(const fdem::Engine& e, long step, double time, int stage);
  /// bolts_NNNN.vtp (`file`) of the profiles record() took, listed in
  /// bolts.pvd at `time`; nothing while no bolt is installed.
  void write_frame(const std::string& file, const coupling::VtkFieldData& frame);
  /// bolt_NN.csv (final profiles), summary "bolts" and, given `plots`,
  /// bolt_forces.png (force_curves).
  void finish(const fdem::Engine& e, RunRecord& summary, PlotWriter* plots) const;
  /// One bolt's summary entry; writes its bolt_NN.csv when installed.
  BoltFigures summary_entry(const fdem::Engine& e, std::size_t b,
                            const std::vector<fdem::BoltStation>& final_profile) const;
  /// bolt_forces.png's curves: kN per bar against the distance from the
  /// collar, one per installed bolt (final state).
  std::vector<plots::PlotSeries> force_curves(const fdem::Engine& e) const;
  /// What a restart needs: bolts.csv so far and the frames written.
  nlohmann::json state() const;
  /// Puts state() back; frames are copied from `from_dir` unless it is `dir`.
  void restore(const nlohmann::json& state, const std::string& from_dir);

 private:
  const fdem::BoltPlan& plan_;
  std::vector<std::uint8_t> is_cable_;
  std::string dir_;
  std::string csv_;                                  ///< bolts.csv so far
  std::vector<std::vector<fdem::BoltStation>> now_;  ///< per bolt, empty when not installed
  coupling::PvdCollection pvd_;
};

/// "bolt_NN" for bolt b.
std::string bolt_name(std::size_t b);

}  // namespace rockfdem::workflows
