// What a specimen run (UCS, Brazilian disc) writes: history.csv (the
// platen's stress and strain, broken counts and energy terms per output
// step), ParaView frames, stress_strain.png and summary.json with the
// peak. The load_platens stage reads the peak every step through load().
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "outputs/history.hpp"
#include "outputs/last_good.hpp"
#include "outputs/step_outputs.hpp"
#include "record/run_context.hpp"
#include "record/summary.hpp"
#include "rockfdem/coupling/vtk_writer.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "stages/platen_load.hpp"

namespace rockfdem::workflows {

class SpecimenOutputs : public StepOutputs {
 public:
  SpecimenOutputs(const Scene& scene, const RunContext& ctx, RunRecord& summary);
  /// The platens' load: the stage's peak and post-peak stop, the rows' stress.
  PlatenLoad& load() { return load_; }
  void record_rows(const fdem::Engine& e, const mesh::Mesh& m, const StageTag& stage,
                   double support_ratio, const fdem::EnergyBalance& energy) override;
  void record_frame(const fdem::Engine& e, const mesh::Mesh& m, const StageTag& stage,
                    const fdem::EnergyBalance& energy, PhaseTimer& timer) override;
  /// What a restart needs: history rows, frames, the peak and stop.
  nlohmann::json state() const;
  /// Refuses (InputError) a state() whose rows do not fit history.csv,
  /// before anything is written.
  void check_fits(const nlohmann::json& state) const;
  /// Puts state() back; frames are copied from `from_dir` when the restart
  /// writes to another directory.
  void restore(const nlohmann::json& state, const std::string& from_dir);
  /// Plots, the engine's figures (with `energy`'s end warning) and the
  /// peak; writes summary.json.
  void finish(const fdem::Engine& e, PhaseTimer& timer);
  /// summary.json of a run a NumericalError stopped: the last good state.
  void report_failure(const fdem::Engine& e, PhaseTimer& timer, const std::string& why);
  /// summary.json of a run a signal stopped (after its checkpoint).
  void report_interrupted(const fdem::Engine& e, PhaseTimer& timer, const std::string& why);

 private:
  void write_frame(const fdem::Engine& e, const mesh::Mesh& m, const std::string& stage);
  void write_summary(PhaseTimer& timer);

  const Scene& scene_;
  const RunContext& ctx_;
  RunRecord& summary_;
  bool disc_;
  PlatenLoad load_;
  History history_;
  coupling::PvdCollection pvd_;
  int frame_ = 0;
  LastGoodState last_good_;
};

}  // namespace rockfdem::workflows
