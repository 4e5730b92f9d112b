// Installing solid bolts through the public Engine API (bolt_install.hpp).
#include "rockfdem/fdem/bolt_install.hpp"

#include <string>

#include "rockfdem/error.hpp"

namespace rockfdem::fdem {
namespace {

/// Uniaxial modulus of a material in the model's plane: plane strain holds
/// the out-of-plane strain at zero, which stiffens a strip by 1 / (1 - nu^2).
double uniaxial_modulus(const Material& m, Plane plane) {
  return plane == Plane::kStrain ? m.young / (1 - m.poisson * m.poisson) : m.young;
}

}  // namespace

BoltPlan plan_bolts(ModelInput& in, const std::vector<BoltSpec>& specs) {
  BoltPlan plan;
  plan.specs = specs;
  std::vector<Bolt> bolts;
  for (const auto& s : specs) bolts.push_back(s.bolt);
  plan.marks = mark_bolts(in, bolts);
  if (in.fracture.empty()) in.fracture.assign(in.triangles.size(), 0);
  const std::size_t n = specs.size();
  plan.owned.resize(n);
  plan.alpha.resize(n);
  plan.installed_stress.resize(n);
  plan.installed.assign(n, 0);
  for (std::size_t b = 0; b < n; ++b) {
    if (plan.marks.triangles[b].empty())
      throw InputError("fdem bolts: bolt " + std::to_string(b) +
                       " marks no triangle; check its head and end against the mesh");
    for (int t : plan.marks.triangles[b]) {
      in.fracture[t] = 1;  // crack elements only exist where fracture is allowed
      if (plan.marks.owner[t] == int(b)) plan.owned[b].push_back(t);
    }
  }
  for (std::size_t b = 0; b < n; ++b) {
    const BoltSpec& s = specs[b];
    plan.strips.push_back(bolt_strip(in, plan.marks, int(b), s.bolt));
    plan.steel.push_back(bolt_steel_model(s.steel, s.row_spacing, s.bolt, plan.strips.back()));
    plan.steel_material.push_back(int(in.materials.size()));
    in.materials.push_back(plan.steel.back().crack);
    plan.grout_material.push_back(int(in.materials.size()));
    in.materials.push_back(s.grout);
    for (int t : plan.owned[b]) {
      const double alpha =
          plan.steel[b].triangle_modulus / uniaxial_modulus(in.materials[in.material[t]], in.plane);
      if (!(alpha > 0 && alpha <= 1e3))
        throw InputError("fdem bolts: bolt " + std::to_string(b) + " needs stiffness factor " +
                         std::to_string(alpha) + " on triangle " + std::to_string(t) +
                         " (steel over rock modulus); the engine allows (0, 1000]");
      plan.alpha[b].push_back(alpha);
    }
    plan.installed_stress[b].assign(plan.owned[b].size(), {0, 0, 0});
  }
  return plan;
}

namespace {

/// Every bolt's crack elements in one pass: both triangles owned by the
/// same bolt, its steel; owned by one bolt or by two different ones, grout
/// of each owner (owner -1: rock).
std::vector<BoltCracks> cracks_by_bolt(const Engine& engine, const BoltPlan& plan) {
  std::vector<BoltCracks> out(plan.specs.size());
  if (out.empty()) return out;  // no marks either: a scene without bolts
  const std::vector<int>& owner = plan.marks.owner;
  for (std::size_t c = 0; c < engine.n_cracks(); ++c) {
    const auto tri = engine.crack_triangles(c);
    const int b0 = owner[tri[0]], b1 = owner[tri[1]];
    if (b0 == b1) {
      if (b0 >= 0) out[b0].steel.push_back(int(c));
      continue;
    }
    for (const int b : {b0, b1})
      if (b >= 0) out[b].grout.push_back(int(c));
  }
  return out;
}

}  // namespace

void index_bolt_cracks(const Engine& engine, BoltPlan& plan) {
  plan.cracks = cracks_by_bolt(engine, plan);
}

BoltCracks bolt_cracks(const Engine& engine, const BoltPlan& plan, int b) {
  if (plan.cracks.size() == plan.specs.size()) return plan.cracks[b];
  return cracks_by_bolt(engine, plan)[b];
}

BoltInstallReport install_bolt(Engine& engine, BoltPlan& plan, int b, BoltStart start) {
  if (b < 0 || std::size_t(b) >= plan.specs.size())
    throw InputError("fdem bolts: no bolt " + std::to_string(b) + " in the plan (" +
                     std::to_string(plan.specs.size()) + " bolts)");
  BoltInstallReport report;
  if (plan.cracks.size() != plan.specs.size()) index_bolt_cracks(engine, plan);
  for (std::size_t i = 0; i < plan.owned[b].size(); ++i) {
    const int t = plan.owned[b][i];
    const double alpha = plan.alpha[b][i];
    const auto current = engine.triangle_stress(t);
    engine.set_stiffness_factor(t, alpha);
    engine.set_active(t, true, ActivationReference::kCurrent);
    if (start == BoltStart::kKeepCurrentStress) {
      engine.set_initial_stress(t, {current[0] / alpha, current[1] / alpha, current[2] / alpha});
      plan.installed_stress[b][i] = current;
    } else {
      engine.set_initial_stress(t, {0, 0, 0});
      plan.installed_stress[b][i] = {0, 0, 0};
    }
    ++report.triangles;
  }
  // Re-joined after the triangles so that their new zero is the installed
  // state; keeping the stress, each also keeps the traction it carries, so
  // that no node feels the installation.
  const BoltCracks cracks = bolt_cracks(engine, plan, b);
  const auto rejoin = [&](int c, int material) {
    if (start == BoltStart::kKeepCurrentStress)
      report.clipped_points += engine.rejoin_crack_keeping_traction(c, material);
    else
      engine.rejoin_crack(c, material);
  };
  for (int c : cracks.steel) rejoin(c, plan.steel_material[b]);
  for (int c : cracks.grout) rejoin(c, plan.grout_material[b]);
  report.steel_cracks = long(cracks.steel.size());
  report.grout_cracks = long(cracks.grout.size());
  plan.installed[b] = 1;
  return report;
}

BoltInstallReport install_bolts(Engine& engine, BoltPlan& plan, BoltStart start) {
  BoltInstallReport total;
  for (std::size_t b = 0; b < plan.specs.size(); ++b) {
    if (plan.installed[b]) continue;
    const BoltInstallReport r = install_bolt(engine, plan, int(b), start);
    total.triangles += r.triangles;
    total.steel_cracks += r.steel_cracks;
    total.grout_cracks += r.grout_cracks;
    total.clipped_points += r.clipped_points;
  }
  return total;
}

}  // namespace rockfdem::fdem
