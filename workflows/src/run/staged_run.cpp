#include "run/staged_run.hpp"

#include <istream>
#include <sstream>
#include <stdexcept>
#include <streambuf>

#include "outputs/run_outputs.hpp"
#include "outputs/specimen_outputs.hpp"
#include "record/output_dir.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/mesh/build.hpp"
#include "run/process_memory.hpp"

namespace rockfdem::workflows {
namespace {

/// A stream over a string's bytes where they are (an istringstream would
/// copy them).
class BytesInPlace : public std::streambuf {
 public:
  explicit BytesInPlace(std::string& s) { setg(s.data(), s.data(), s.data() + s.size()); }
};

}  // namespace

template <class Outputs>
StagedRun<Outputs>::StagedRun(const Scene& scene, const RunContext& ctx)
    : scene_(scene),
      ctx_(ctx),
      restart_(!ctx.restart.empty()),
      resume_(restart_ ? read_checkpoint(ctx.restart, scene) : Checkpoint{}),
      checkpoint_every_(ctx.checkpoint_every >= 0 ? ctx.checkpoint_every
                                                  : scene.output.checkpoint_every),
      record_(scene, ctx.threads),
      out_(scene, ctx, record_) {}

template <class Outputs>
void StagedRun<Outputs>::make_mesh() {
  mesh::MeshReport report;
  mesh_ = keeping_threads(ctx_, [&] { return mesh::build_mesh(scene_.mesh, &report); });
  release_phase_memory();  // gmsh's model and code
  record_.record_mesh(mesh_, report);
  timer_.stamp("mesh");
}

template <class Outputs>
void StagedRun<Outputs>::set_engine(fdem::Engine&& engine) {
  if (engine_) throw std::logic_error("the run's engine is given once");
  engine_.emplace(std::move(engine));
}

template <class Outputs>
void StagedRun<Outputs>::load_resumed_engine() {
  BytesInPlace bytes(resume_.engine_state);
  std::istream in(&bytes);
  engine_->load_state(in);
  std::string().swap(resume_.engine_state);
}

template <class Outputs>
void StagedRun<Outputs>::write_summary(const std::string& status) {
  record_.status = status;
  record_.set_timings(timer_);
  record_.write(output_path(ctx_.output_dir, "summary.json"));
}

template <class Outputs>
void StagedRun<Outputs>::resume_or_record(StageRunner& stages, const StageTag& first) {
  if (restart_) {
    try {
      out_.restore(resume_.run.at("outputs"), run_dir_of(ctx_.restart));
      stages.restore(resume_.run.at("stages"));
    } catch (const InputError& e) {
      throw InputError(ctx_.restart + ": " + e.what());
    }
    record_.restarted_from = CheckpointMark{ctx_.restart, engine().step_count()};
  } else {
    reporting_failure([&] { stages.record_output(first, timer_); });
  }
  stages.set_checkpoint(checkpoint_every_, [this, &stages] { save_checkpoint(stages); });
}

template <class Outputs>
void StagedRun<Outputs>::reporting_failure(const std::function<void()>& f) {
  try {
    f();
  } catch (const NumericalError& err) {
    fail(err.what());
  }
}

template <class Outputs>
void StagedRun<Outputs>::fail(const std::string& what) {
  const std::string why = failure_message(what);
  out_.report_failure(engine(), timer_, why);
  throw NumericalError(why);
}

template <class Outputs>
void StagedRun<Outputs>::output_failed(const OutputError& e) {
  const std::string summary = output_path(ctx_.output_dir, "summary.json");
  std::string note = "; " + summary + " records the failure";
  try {
    if (!engine_) throw OutputError("no engine yet");
    out_.report_failure(engine(), timer_, e.what());  // the summary, then report.md
  } catch (const std::exception& first) {
    // The summary alone, small, where the full report did not fit.
    try {
      record_.failure = e.what();
      write_summary("failed");
    } catch (const std::exception& again) {
      note = "; " + summary + " could not be written either (" + again.what() + ")";
    }
  }
  throw OutputError(e.what() + note);
}

template <class Outputs>
void StagedRun<Outputs>::save_checkpoint(const StageRunner& stages) {
  Checkpoint c;
  c.run = {{"stages", stages.state()}, {"outputs", out_.state()}};
  add_run_state(c.run);
  std::ostringstream bytes;
  engine().save_state(bytes);
  c.engine_state = bytes.str();
  const std::string path = write_checkpoint(ctx_.output_dir, engine().step_count(), scene_, c);
  record_.checkpoint = CheckpointMark{path, engine().step_count()};
}

template class StagedRun<RunOutputs>;
template class StagedRun<SpecimenOutputs>;

}  // namespace rockfdem::workflows
