#include "run/continuum_solve.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "record/number_text.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/insitu/plastic.hpp"
#include "run/continuum_ground_reaction.hpp"
#include "run/engine_setup.hpp"
#include "run/field_sampler.hpp"
#include "stages/registry.hpp"
#include "stages/stage.hpp"

namespace rockfdem::workflows {
namespace {

// The stages' own checks walked again over the scene, for what each stage
// does to the core's factor and the lining. A stage the order does not
// allow changes nothing: the default sequence removes a core that an
// implicit alpha of 0 already took out.
class Replay : public StageCheck {
 public:
  struct Refused {};
  using StageCheck::StageCheck;
  [[noreturn]] void refuse(const std::string&, const std::string&) const override {
    throw Refused{};
  }
  void require(const std::string&, const std::string&) const override {}
};

/// The alphas of the scene's construction sequence, ending at 0, and the
/// alpha at which its lining stage installs the lining (-1: none).
std::vector<double> construction_alphas(const Scene& s, double* lining_alpha) {
  std::vector<double> alphas = s.insitu.alpha;
  StageOrder order;
  order.alpha = alphas.back();
  *lining_alpha = s.insitu.lining_active ? insitu::LiningStage{}.install_alpha : -1;
  for (const StageSpec& st : s.stages) {
    const StageOrder before = order;
    try {
      Replay replay(s, st, order);
      stage_of(st.kind).check(replay);
    } catch (const Replay::Refused&) {
      order = before;
    }
    if (order.alpha < before.alpha) alphas.push_back(order.alpha);
    if (order.lined && !before.lined && *lining_alpha < 0) *lining_alpha = before.alpha;
  }
  if (order.alpha > 0) alphas.push_back(0);
  return alphas;
}

insitu::InsituField field_of(const insitu::PlasticField& p) {
  insitu::InsituField f;
  f.alpha = 1 - p.lambda;
  f.lining_installed = p.lining_installed;
  f.stress = p.stress;
  f.active = p.active;
  f.ux = p.ux;
  f.uy = p.uy;
  f.unbalanced_ratio = p.unbalanced_ratio;
  return f;
}

/// The elastic counterpart's problem: the scene's in-situ problem over the
/// whole construction sequence c.alphas, the lining joining where its stage
/// puts it.
insitu::InsituSpec elastic_spec(const Scene& scene, const ContinuumStates& c) {
  insitu::InsituSpec spec = insitu_spec(scene);
  spec.alphas = c.alphas;
  if (c.lining_alpha > 0 && !scene.insitu.lining_active) {
    // In the next stage, on the ground as this alpha left it (the engine's
    // lining stage installs on the state it finds).
    spec.lining.active = true;
    spec.lining.install_alpha = c.lining_alpha * (1 - 1e-9);
  }
  return spec;
}

void solve_elastic(const Scene& scene, const mesh::Mesh& m, ContinuumStates& c) {
  insitu::InsituSpec spec = elastic_spec(scene, c);
  spec.keep_fields = {scene.insitu.alpha.back(), c.alphas.back()};  // the hand-off's, the end's
  const std::vector<insitu::InsituField> fields = insitu::solve_insitu(m, spec);
  for (const auto& f : fields)
    if (f.alpha == scene.insitu.alpha.back()) c.handoff = f;
  c.end = fields.back();
}

/// The Mohr-Coulomb problem of the sequence c: the scene's loading with the
/// lining joining at c.lining_alpha, the rock's peak strength, the release
/// lambda = 1 - alpha of each alpha below 1.
void plastic_problem(const Scene& scene, const ContinuumStates& c, insitu::InsituSpec& spec,
                     insitu::PlasticSpec& p) {
  spec = insitu_spec(scene);
  spec.lining.active = c.lining_alpha > 0;
  if (spec.lining.active) spec.lining.install_alpha = c.lining_alpha;
  const MaterialSpec& rock = scene.materials.at(mesh::kRock);
  p.rock = {rock.cohesion, rock.friction_angle, scene.insitu.dilation_angle};
  p.release.clear();
  for (const double a : c.alphas)
    if (a < 1) p.release.push_back(1 - a);
}

void solve_plastic(const Scene& scene, const mesh::Mesh& m, ContinuumStates& c) {
  insitu::InsituSpec spec;
  insitu::PlasticSpec p;
  plastic_problem(scene, c, spec, p);
  const std::vector<insitu::PlasticField> fields = insitu::solve_mohr_coulomb(m, spec, p);
  c.handoff.alpha = -1;  // none when the implicit stage stops at alpha = 1
  for (const auto& f : fields)
    if (std::abs(1 - f.lambda - scene.insitu.alpha.back()) < 1e-12) c.handoff = field_of(f);
  c.end = field_of(fields.back());
  c.yielded = fields.back().yielded;
  c.n_yielded = fields.back().n_yielded;
}

/// Whether a yielded triangle touches the outer boundary of the model.
bool yield_reaches_boundary(const mesh::Mesh& m, const std::vector<std::uint8_t>& yielded) {
  std::vector<std::uint8_t> outer(m.n_vertices(), 0);
  for (const auto& e : m.edges)
    if (e.tag >= mesh::kBottom && e.tag <= mesh::kLeft) outer[e.a] = outer[e.b] = 1;
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    if (yielded[t])
      for (const int v : m.triangles[t])
        if (outer[v]) return true;
  return false;
}

/// The Mohr-Coulomb ground reaction curve at the key points; one that
/// cannot be solved is named in "skipped" and the comparison stands.
void add_ground_reaction(const Scene& scene, const RunContext& ctx, const mesh::Mesh& m,
                         const fdem::Engine& e, const std::vector<Monitor>& monitors,
                         RunRecord& summary) {
  std::vector<WallPoint> points;
  for (const Monitor& mon : monitors)
    points.push_back({mon.name, e.node_vertex()[mon.node], mon.inward_x, mon.inward_y});
  try {
    summary.continuum_comparison->ground_reaction =
        keeping_threads(ctx, [&] { return mohr_coulomb_ground_reaction(scene, m, points); });
  } catch (const std::runtime_error& err) {
    summary.skipped.push_back(std::string("continuum ground reaction curve: ") + err.what());
  }
}

std::string skip_text(const Scene& scene, const std::runtime_error& err) {
  return std::string("continuum comparison (insitu.continuum = ") + scene.insitu.continuum +
         "): " + err.what();
}

/// The counterpart's model and sequence, nothing solved yet.
ContinuumStates unsolved_states(const Scene& scene) {
  ContinuumStates c;
  c.model = scene.insitu.continuum;
  c.alphas = construction_alphas(scene, &c.lining_alpha);
  return c;
}

bool removes_core(const Scene& scene) {
  return std::any_of(scene.stages.begin(), scene.stages.end(),
                     [](const StageSpec& st) { return st.kind == "remove_core"; });
}

}  // namespace

std::optional<CounterpartTail> counterpart_tail(const Scene& scene, insitu::InsituSpec& spec) {
  if (!removes_core(scene) || scene.insitu.continuum == "mohr_coulomb") return std::nullopt;
  CounterpartTail t{unsolved_states(scene)};
  const ContinuumStates& c = t.states;
  const insitu::InsituSpec whole = elastic_spec(scene, c);
  // The sequence must begin with the implicit stage's own problem: the
  // lining (if it joins) only below the last alpha, nothing else changed.
  const std::size_t n = spec.alphas.size();
  if (whole.alphas.size() < n ||
      !std::equal(spec.alphas.begin(), spec.alphas.end(), whole.alphas.begin()))
    return std::nullopt;
  if (whole.lining.active && !spec.lining.active &&
      !(whole.lining.install_alpha < spec.alphas.back()))
    return std::nullopt;
  t.implicit_alphas = n;
  t.handoff_is_runs = !scene.insitu.handoff_first_crack;
  spec.alphas = whole.alphas;
  spec.lining = whole.lining;
  return t;
}

void CounterpartTail::take(insitu::InsituField& f) {
  const bool last = seen + 1 == states.alphas.size();
  if (seen + 1 == implicit_alphas) {
    if (handoff_is_runs) {  // the run holds it whole until the comparison
      states.handoff.alpha = f.alpha;
      states.handoff_is_runs = true;
    } else {
      states.handoff = f;  // a copy: the implicit stage's sampler may free these arrays
    }
    if (last) states.end = f;
  } else if (seen >= implicit_alphas) {
    states.seconds += f.total_seconds;
    if (last) states.end = std::move(f);
    release_arrays(f);  // the counterpart compares only its hand-off and its end
  }
  ++seen;
}

ContinuumStates solve_continuum_counterpart(const Scene& scene, const mesh::Mesh& m) {
  const auto start = std::chrono::steady_clock::now();
  ContinuumStates c = unsolved_states(scene);
  if (c.model == "mohr_coulomb")
    solve_plastic(scene, m, c);
  else
    solve_elastic(scene, m, c);
  c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return c;
}

PostPeakCounterpart solve_post_peak_counterpart(const Scene& scene, const mesh::Mesh& m) {
  ContinuumStates c;
  c.alphas = construction_alphas(scene, &c.lining_alpha);
  insitu::InsituSpec spec;
  insitu::PlasticSpec p;
  plastic_problem(scene, c, spec, p);
  PostPeakCounterpart out;
  out.residual_friction_deg = scene.materials.at(mesh::kRock).residual_friction_angle;
  p.residual = insitu::ResidualStrength{0, out.residual_friction_deg, 0};
  // A verdict, not a field: give up on a failing step sooner than the
  // counterpart itself does (25 iterations, 8 halvings); on the unlined test
  // scene 39 s instead of 130 s, the same verdict.
  p.max_newton = 12;
  p.max_halvings = 5;
  // Ground at the limit of collapse can creep on at the smallest step for
  // as long as the release lasts (over 15 min on the unlined test scene in
  // one element order, 62 s in another): 40 failed steps is a verdict.
  p.max_failed_steps = 40;
  // Where the release gives way is part of the verdict: the last state
  // reached comes back instead of an error.
  p.stop_at_failure = true;
  p.output_at_failure = true;
  insitu::validate(p);  // InputError: the strengths cannot be posed this way
  std::vector<insitu::PlasticField> fields;
  try {
    fields = insitu::solve_mohr_coulomb(m, spec, p);
  } catch (const NumericalError& e) {
    out.reason = e.what();
    return out;
  }
  if (fields.empty()) {
    out.reason = "the first release step failed: the ground cannot stand at the hand-off";
    return out;
  }
  const insitu::PlasticField& f = fields.back();
  out.alpha = 1 - f.lambda;
  out.n_yielded = f.n_yielded;
  if (f.lambda < p.release.back() - 1e-12) {
    out.reason = "the release stops at alpha = " + fixed(out.alpha, 4) + " (" +
                 std::to_string(f.n_yielded) + " triangles yielded)";
    if (c.lining_alpha > 0)
      out.reason += std::string(": the ground gives way ") +
                    (out.alpha > c.lining_alpha ? "before" : "after") +
                    " the support goes in at alpha = " + fixed(c.lining_alpha, 4);
    return out;
  }
  out.equilibrium = !yield_reaches_boundary(m, f.yielded);
  if (!out.equilibrium)
    out.reason = "the plastic zone reaches the model's outer boundary (" +
                 std::to_string(f.n_yielded) + " triangles yielded)";
  return out;
}

namespace {

// The open excavation as a continuum: the scenes without a ring compare
// their relaxed state with it.
insitu::InsituField solve_open_hole(const Scene& scene, const RunContext& ctx,
                                    const mesh::Mesh& m) {
  insitu::InsituSpec open = insitu_spec(scene);
  open.alphas = {0.0};
  open.lining.active = false;
  return keeping_threads(ctx, [&] { return insitu::solve_insitu(m, open).back(); });
}

}  // namespace

ContinuumReferences solve_continuum_references(const Scene& scene, const RunContext& ctx,
                                               const mesh::Mesh& m,
                                               std::optional<ContinuumStates> counterpart) {
  ContinuumReferences r;
  if (!removes_core(scene)) return r;
  if (!scene.lining_ring) r.open_hole = solve_open_hole(scene, ctx, m);
  // A counterpart that cannot be solved leaves the run's own results standing.
  try {
    r.counterpart =
        counterpart ? std::move(counterpart)
                    : keeping_threads(ctx, [&] { return solve_continuum_counterpart(scene, m); });
    if (scene.insitu.continuum_post_peak) {
      const auto start = std::chrono::steady_clock::now();
      r.post_peak = keeping_threads(ctx, [&] { return solve_post_peak_counterpart(scene, m); });
      r.post_peak->seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  } catch (const InputError& err) {
    r.skipped.push_back(skip_text(scene, err));
  } catch (const NumericalError& err) {
    r.skipped.push_back(skip_text(scene, err));
  }
  return r;
}

void compare_with_continuum_counterpart(const Scene& scene, const RunContext& ctx,
                                        const mesh::Mesh& m, const fdem::Engine& e,
                                        const insitu::InsituField& fdem_handoff,
                                        const ContinuumReferences& solved,
                                        const std::vector<Monitor>& monitors,
                                        const std::vector<char>& bolted, RunRecord& summary) {
  for (const std::string& s : solved.skipped) summary.skipped.push_back(s);
  if (!solved.counterpart) return;
  const ContinuumStates& c = *solved.counterpart;
  try {
    summary.continuum_comparison = compare_with_counterpart(
        scene, m, e, fdem_handoff, c, monitors, bolted, ctx.output_dir, summary, ctx.quiet);
    if (c.model == "mohr_coulomb") add_ground_reaction(scene, ctx, m, e, monitors, summary);
    summary.continuum_post_peak = solved.post_peak;
  } catch (const InputError& err) {
    summary.skipped.push_back(skip_text(scene, err));
  } catch (const NumericalError& err) {
    summary.skipped.push_back(skip_text(scene, err));
  }
}

}  // namespace rockfdem::workflows
