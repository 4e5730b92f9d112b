#include "run/stage_runner.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "record/output_dir.hpp"
#include "record/summary.hpp"
#include "rockfdem/error.hpp"
#include "run/interrupt.hpp"
#include "run/process_memory.hpp"
#include "run/progress.hpp"
#include "run/rigid_rotation_guard.hpp"
#include "stages/registry.hpp"

namespace rockfdem::workflows {

StageRunner::StageRunner(fdem::Engine& engine, const mesh::Mesh& m,
                         const insitu::InsituField& handoff, const Scene& scene,
                         const RunContext& ctx, StepOutputs& out, const KeyPoints& key_points,
                         fdem::BoltPlan& bolts, SupportMaterials materials)
    : model_{engine,
             m,
             ctx,
             scene,
             bolts,
             materials,
             handoff.alpha,
             handoff.alpha,
             handoff.alpha > 0,
             handoff.lining_installed},
      engine_(engine),
      out_(out),
      scene_(scene),
      key_points_(key_points),
      energy_(scene, m) {
  out_.set_lining_installed(model_.lining_installed);
}

std::vector<double> StageRunner::monitor_displacements() const {
  std::vector<double> u;
  for (const Monitor& m : monitors()) {
    const std::array<double, 2> d = engine_.displacement(std::size_t(m.node));
    u.push_back(d[0]);
    u.push_back(d[1]);
  }
  return u;
}

double StageRunner::settle_measure(long steps) {
  const std::vector<double> now = monitor_displacements();
  double change = 0, size = 0;
  // cursor_.monitor_u holds the same monitors, set when the stage began.
  for (std::size_t i = 0; i + 1 < now.size(); i += 2) {
    const double* prev = &cursor_.monitor_u[i];
    const double moved = std::hypot(now[i] - prev[0], now[i + 1] - prev[1]);
    if (moved > change) {
      change = moved;
      moving_most_ = monitors()[i / 2].name;
    }
    size = std::max(size, std::hypot(now[i], now[i + 1]));
  }
  cursor_.monitor_u = now;
  // Per 1000 steps, so that the tolerance does not depend on every_steps.
  last_rate_ = steps > 0 ? change * (1000.0 / double(steps)) : 0.0;
  return size > 0 && steps > 0 ? change / size * (1000.0 / double(steps)) : 0.0;
}

std::optional<double> StageRunner::broken_growth(long steps) {
  const long now = long(engine_.broken_counts().total());
  const long before = cursor_.broken;
  cursor_.broken = now;
  if (before < 0 || steps <= 0) return std::nullopt;
  return now > 0 ? double(now - before) / double(now) * (1000.0 / double(steps)) : 0.0;
}

bool StageRunner::advance(long n, const StopTest& stop, bool* reached) {
  for (long i = 0; i < n; ++i) {
    if (interrupt_requested()) return false;
    engine_.step();
    if (stop && stop()) {
      *reached = true;
      return true;
    }
  }
  return true;
}

namespace {

// The key points' trend: the largest monitor move per 1000 steps averaged
// over the last kWindow outputs against its average over the kWindow
// before. Means over long windows, because a cracking model moves in
// bursts: the default tunnel's floor, heaving at a steady 2 mm per 1000
// steps, moved 0.5 to 3.8 mm from one output to the next, and 5-output
// means differed by 2x with no trend.
constexpr std::size_t kWindow = 10;
constexpr double kAccelerating = 1.5;  ///< last / before above this: accelerating

// last / before, or 0 while fewer than 2 kWindow outputs are known.
double trend(const std::vector<double>& rates) {
  if (rates.size() < 2 * kWindow) return 0.0;
  double before = 0, last = 0;
  for (std::size_t i = 0; i < kWindow; ++i) {
    before += rates[rates.size() - 2 * kWindow + i];
    last += rates[rates.size() - kWindow + i];
  }
  return before > 0 ? last / before : 0.0;
}

// What the key points still move if their rate keeps falling by the trend
// r per window: the geometric series d r / (1 - r) of the last window's
// move d [m]; unbounded when the rate does not fall.
double remaining_move(const std::vector<double>& rates, double r, long every_steps) {
  if (rates.size() < kWindow) return 0.0;
  if (r >= 1) return std::numeric_limits<double>::infinity();
  double per_1000 = 0;
  for (std::size_t i = rates.size() - kWindow; i < rates.size(); ++i) per_1000 += rates[i];
  const double window_move = per_1000 * double(every_steps) / 1000.0;
  return window_move * r / (1 - r);
}

}  // namespace

bool StageRunner::unstable(const StageSpec& stage, bool criteria) {
  cursor_.rates.push_back(last_rate_);
  if (cursor_.rates.size() > 2 * kWindow) cursor_.rates.erase(cursor_.rates.begin());
  const auto [name, u] = key_points_.largest(engine_, monitors());
  const double span = key_points_.span();
  const double limit = stage.unstable_fraction * span;
  const bool beyond = span > 0 && u > limit;
  // Both trends count only once the stage is 2 kWindow outputs old (past
  // its first transient). Accelerating while far from settled is a
  // collapse under way. With the forces balanced (ratio met, settle not),
  // a rate that does not fall fast enough to stop within the limit is a
  // mechanism flowing at the limit of equilibrium, as explicit codes read
  // a steady velocity field at a low unbalanced-force ratio: projected
  // forward at its trend, the motion passes the span fraction (or never
  // stops).
  const double r = trend(cursor_.rates);
  const bool speeding = r > kAccelerating && last_settle_ > 10 * stage.settle;
  const double projected = u + remaining_move(cursor_.rates, r, stage.every_steps);
  const bool flowing = criteria && r > 0 && last_settle_ > stage.settle &&
                       engine_.unbalanced_force_ratio() < stage.ratio && span > 0 &&
                       projected > limit;
  if (!beyond && !speeding && !flowing) return false;
  char projection[200] = "";
  if (flowing && !beyond && !speeding && std::isfinite(projected))
    std::snprintf(projection, sizeof projection,
                  "; with the forces balanced, at that trend it would stop only after %.0f mm, "
                  "beyond the limit: a mechanism flowing",
                  1000 * projected);
  else if (flowing && !beyond && !speeding)
    std::snprintf(projection, sizeof projection,
                  "; with the forces balanced and the rate not falling: a mechanism flowing");
  char msg[800];
  std::snprintf(msg, sizeof msg,
                "stage '%s', step %ld: key point %s has moved %.0f mm (%.3g of the span %.2f m; "
                "limit %g) and %s moves %.3g mm per 1000 steps (%.2f times the rate of the 10 "
                "outputs before)%s%s: the opening is closing, not stabilising",
                stage.kind.c_str(), engine_.step_count(), name.c_str(), 1000 * u,
                span > 0 ? u / span : 0.0, span, stage.unstable_fraction, moving_most_.c_str(),
                1000 * last_rate_, r, speeding && !beyond ? ", accelerating" : "", projection);
  if (unstable_.message.empty()) unstable_ = {"unstable", msg};  // the first finding stands
  return true;
}

void StageRunner::interrupted(const StageSpec& stage) {
  // Checkpoint first: the extra row below is not one an uninterrupted run writes.
  if (save_checkpoint_) save_checkpoint_();
  record_step(stage);
  const int sig = interrupt_requested();
  throw Interrupted(sig, "interrupted by " + signal_text(sig) + " at step " +
                             std::to_string(engine_.step_count()) + " in stage '" + stage.kind +
                             "'; outputs and a checkpoint are written");
}

void StageRunner::record_output(const StageTag& stage, PhaseTimer& timer) {
  // One ledger per output step (a sweep over every element) for the row,
  // the check and the last good state.
  const fdem::EnergyBalance energy = engine_.energy_balance();
  out_.record_rows(engine_, model_.mesh, stage, model_.support_ratio(), energy);
  // Before the frame: the last frame stays the last good state.
  energy_.at_output_step(energy, engine_.step_count());
  check_rigid_rotation({0, 0, out_.outer_rotation(engine_)}, scene_.insitu.rollers,
                       engine_.step_count());
  out_.record_frame(engine_, model_.mesh, stage, energy, timer);
}

bool StageRunner::criterion_met(const StageSpec& stage, bool tested, bool reached) {
  if (tested) return reached;
  // Equilibrium: balanced forces alone are not enough while cracks keep
  // breaking and blocks keep sliding (the ratio then stalls near 1e-3
  // with the walls still converging); the monitors must have settled
  // too, and both must hold at `hold` consecutive outputs, so that a
  // ratio met once on the way to a collapse does not count.
  // Key points can settle while cracks still break away from them: where
  // the scene asks, the broken count must have settled as well.
  const bool cracks_settled = stage.broken_settle <= 0 ||
                              (last_broken_growth_ && *last_broken_growth_ <= stage.broken_settle);
  const bool met = engine_.unbalanced_force_ratio() < stage.ratio &&
                   (stage.settle <= 0 || last_settle_ <= stage.settle) && cracks_settled;
  cursor_.held = met ? cursor_.held + 1 : 0;
  return cursor_.held >= stage.hold;
}

void StageRunner::checkpoint_if_due() {
  if (checkpoint_every_ > 0 && save_checkpoint_ &&
      engine_.step_count() - last_checkpoint_ >= checkpoint_every_) {
    save_checkpoint_();
    last_checkpoint_ = engine_.step_count();
    timer_->stamp("checkpoint");
  }
}

bool StageRunner::step_until(const StageSpec& stage, const StopTest& stop) {
  Progress progress(stage.kind, stage.max_steps, model_.ctx.quiet);
  const long first = cursor_.first;
  const double t0 = cursor_.t0;
  const auto in_stage = [&] { return engine_.step_count() - first; };
  const auto out_of_time = [&] { return stage.time > 0 && engine_.time() - t0 >= stage.time; };
  bool done = false;
  while (in_stage() < stage.max_steps && !done && !out_of_time()) {
    const long chunk = std::min<long>(stage.every_steps - in_stage() % stage.every_steps,
                                      stage.max_steps - in_stage());
    timer_->stamp("output");
    const long before = engine_.step_count();
    bool reached = false;
    const bool whole = advance(chunk, stop, &reached);
    // A stage's first step computes the stability limit its changes asked for.
    if (before == first) release_free_heap();
    timer_->stamp("fdem");
    if (!whole) interrupted(stage);
    record_step(stage);
    last_settle_ = settle_measure(engine_.step_count() - before);
    last_broken_growth_ = broken_growth(engine_.step_count() - before);
    done = criterion_met(stage, bool(stop), reached);
    progress.update(in_stage(), engine_.time() - t0);
    if (!done && unstable(stage, !stop) && stage.stop_when_unstable) {
      stopped_ = true;
      break;
    }
    // Only where the loop goes on: a restart resumes inside this stage.
    if (!done && in_stage() < stage.max_steps && !out_of_time()) checkpoint_if_due();
  }
  progress.finish(in_stage(), engine_.time() - t0);
  stage_dt_ = engine_.dt();  // before a grout stage re-joins cracks (a new limit)
  return done;
}

void StageRunner::run(const StageSpec& stage) {
  const Stage& kind = stage_of(stage.kind);
  if (!cursor_.started) {
    cursor_.first = engine_.step_count();
    cursor_.t0 = engine_.time();
    cursor_.changes = kind.apply(model_, stage);
    out_.set_lining_installed(model_.lining_installed);
    cursor_.broken = long(engine_.broken_counts().total());
    if (kind.installs_support()) {
      out_.support_installed(engine_);
      cursor_.changes.broken_at_install = cursor_.broken;
    }
    cursor_.monitor_u = monitor_displacements();
    cursor_.started = true;
  }
  StageChanges done = cursor_.changes;
  last_settle_ = -1;  // no output interval yet
  last_broken_growth_.reset();
  const bool converged = kind.step(*this, stage, done);
  out_.stage_done(engine_, model_.mesh, StageTag{stage.kind, number()}, done);
  report_.push_back(report_entry(stage, done, converged));
}

int StageRunner::number() const {
  const mesh::ModelKind k = scene_.mesh.kind;
  const bool implicit = k != mesh::ModelKind::kUcs && k != mesh::ModelKind::kBrazilian;
  return int(cursor_.index) + (implicit ? 1 : 0);
}

StageRecord StageRunner::report_entry(const StageSpec& stage, const StageChanges& changes,
                                      bool converged) const {
  StageRecord r;
  r.kind = stage.kind;
  r.number = number();
  r.changes = changes;
  r.steps = engine_.step_count() - cursor_.first;
  r.simulated_time = engine_.time() - cursor_.t0;
  if (r.steps > 0) r.dt = stage_dt_;
  r.unbalanced_ratio = engine_.unbalanced_force_ratio();
  if (last_settle_ >= 0) r.settle = last_settle_;
  r.broken_growth = last_broken_growth_;
  r.broken_settle_limit = stage.broken_settle;
  // A stage that took no step has no equilibrium to report.
  if (r.steps > 0) r.converged = converged;
  r.max_steps = stage.max_steps;
  r.ratio = stage.ratio;
  r.settle_limit = stage.settle;
  r.hold = stage.hold;
  r.unstable_fraction = stage.unstable_fraction;
  if (last_settle_ >= 0) r.moving_most = MovingMost{moving_most_, 1000 * last_rate_};
  r.support_pressure_ratio = model_.support_ratio();
  return r;
}

void StageRunner::run_all(PhaseTimer& timer) {
  timer_ = &timer;
  for (; cursor_.index < scene_.stages.size() && !stopped_; ++cursor_.index) {
    run(scene_.stages[cursor_.index]);
    if (stopped_) break;
    Cursor next;  // the next stage starts afresh
    next.index = cursor_.index;
    cursor_ = next;
  }
}

RunVerdict StageRunner::verdict() const {
  if (!unstable_.message.empty()) return unstable_;
  // The last stage that stepped decides: its end is the state reported.
  for (auto it = report_.rbegin(); it != report_.rend(); ++it) {
    const StageRecord& r = *it;
    if (r.steps == 0) continue;
    if (r.converged && *r.converged) return {};
    char msg[600];
    const std::string other = stage_of(r.kind).not_at_equilibrium();
    if (!other.empty()) {
      std::snprintf(msg, sizeof msg, "the last stage that stepped, '%s', %s", r.kind.c_str(),
                    other.c_str());
    } else {
      const std::optional<MovingMost>& m = r.moving_most;
      std::snprintf(msg, sizeof msg,
                    "stage '%s' stopped after %ld steps (cap %ld) without equilibrium: "
                    "unbalanced ratio %.3g (limit %g), settle %.3g (limit %g), key point "
                    "moving most: %s, %.3g mm per 1000 steps",
                    r.kind.c_str(), r.steps, r.max_steps, r.unbalanced_ratio, r.ratio,
                    r.settle ? *r.settle : -1.0, r.settle_limit, m ? m->key_point.c_str() : "none",
                    m ? m->mm_per_1000_steps : 0.0);
      if (r.broken_settle_limit > 0) {
        const std::size_t n = std::strlen(msg);
        std::snprintf(msg + n, sizeof msg - n,
                      ", broken count growing %.3g of itself per 1000 steps (limit %g)",
                      r.broken_growth ? *r.broken_growth : -1.0, r.broken_settle_limit);
      }
    }
    return {"not_at_equilibrium", msg};
  }
  return {};
}

void StageRunner::set_checkpoint(long every, std::function<void()> save) {
  checkpoint_every_ = every;
  save_checkpoint_ = std::move(save);
  last_checkpoint_ = engine_.step_count();
}

nlohmann::json StageRunner::state() const {
  return {{"stage_index", cursor_.index},
          {"stage_started", cursor_.started},
          {"stage_first_step", cursor_.first},
          {"stage_t0", cursor_.t0},
          {"stage_changes", stage_changes_json(cursor_.changes)},
          {"stage_monitor_u", cursor_.monitor_u},
          {"stage_held", cursor_.held},
          {"stage_rates", cursor_.rates},
          {"stage_broken", cursor_.broken},
          {"unstable", unstable_.message},
          {"alpha", model_.alpha},
          {"core_present", model_.core_present},
          {"lining_installed", model_.lining_installed},
          {"report", stage_records_json(report_)},
          {"last_checkpoint", engine_.step_count()}};
}

void check_stage_monitor_u(std::size_t n_values, std::size_t n_key_points,
                           const std::string& where) {
  if (n_values == 2 * n_key_points) return;
  throw InputError(where + "corrupt run state: field 'stages.stage_monitor_u' holds " +
                   std::to_string(n_values) + " values; the model's " +
                   std::to_string(n_key_points) + " key points need " +
                   std::to_string(2 * n_key_points));
}

void StageRunner::restore(const nlohmann::json& s) {
  cursor_.index = s.at("stage_index").get<std::size_t>();
  cursor_.started = s.at("stage_started").get<bool>();
  cursor_.first = s.at("stage_first_step").get<long>();
  cursor_.t0 = s.at("stage_t0").get<double>();
  cursor_.changes = stage_changes_from_json(s.at("stage_changes"));
  cursor_.monitor_u = s.at("stage_monitor_u").get<std::vector<double>>();
  // settle_measure() reads a pair per monitor.
  check_stage_monitor_u(cursor_.monitor_u.size(), monitors().size(), "");
  cursor_.held = s.value("stage_held", 0);
  cursor_.rates = s.value("stage_rates", std::vector<double>{});
  cursor_.broken = s.value("stage_broken", -1L);
  const std::string unstable = s.value("unstable", std::string());
  if (!unstable.empty()) unstable_ = {"unstable", unstable};
  model_.alpha = s.at("alpha").get<double>();
  model_.core_present = s.at("core_present").get<bool>();
  model_.lining_installed = s.at("lining_installed").get<bool>();
  out_.set_lining_installed(model_.lining_installed);
  report_ = stage_records_from_json(s.at("report"));
  last_checkpoint_ = s.at("last_checkpoint").get<long>();
}

}  // namespace rockfdem::workflows
