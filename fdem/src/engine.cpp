// The public Engine: construction from a ModelInput, the explicit step as a
// fixed list of timed phases, stage controls and state access.
//
// One step:
//   1. triangles: finite-strain CST forces into the triangles' slots
//   2. cracks:    crack-law forces into the crack elements' slots, damage
//   3. nodes:     gather slots per node, damping, BCs, central differences
// Each phase is one parallel loop whose iterations write disjoint memory, so
// the result is bit-identical for any thread count. Errors found inside a
// loop are reduced to the lowest offending index and raised after it.
#include "rockfdem/fdem/engine.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "boundary.hpp"
#include "contact.hpp"
#include "crack_elements.hpp"
#include "crack_prestress.hpp"
#include "energy.hpp"
#include "engine_impl.hpp"
#include "joint_friction.hpp"
#include "kinetic_damping.hpp"
#include "node_update.hpp"
#include "parallel.hpp"
#include "simd_isa.hpp"
#include "stable_dt.hpp"
#include "strength_heterogeneity.hpp"
#include "topology.hpp"
#include "triangle_force.hpp"
#include "triangle_geometry.hpp"

namespace rockfdem::fdem {
namespace {

detail::SolidConstants solid_constants(const Material& m, Plane plane) {
  detail::SolidConstants s;
  const double e = m.young, nu = m.poisson;
  s.mu = e / (2.0 * (1.0 + nu));
  s.lambda =
      plane == Plane::kStrain ? e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)) : e * nu / (1.0 - nu * nu);
  s.rho = m.density;
  s.plane_strain = plane == Plane::kStrain;
  s.cp = std::sqrt((s.lambda + 2.0 * s.mu) / s.rho);
  s.cs = std::sqrt(s.mu / s.rho);
  return s;
}

/// eta = ratio * 2 h sqrt(E rho) with h the triangle's smallest altitude.
void set_viscous_damping(detail::EngineData& d) {
  for (std::size_t t = 0; t < d.tris.size(); ++t) {
    const Material& m = d.materials[d.tris.material[t]];
    if (m.damping_ratio <= 0) continue;
    const double h =
        detail::smallest_altitude(d.nodes.pos.data(), &d.tris.nodes[3 * t], d.tris.area0[t]);
    d.tris.eta[t] = m.damping_ratio * 2.0 * h * std::sqrt(m.young * m.density);
  }
  // The energy ledger books each step's viscous force again with the next
  // step's velocities (energy.hpp).
  if (std::any_of(d.tris.eta.begin(), d.tris.eta.end(), [](double e) { return e > 0.0; }))
    d.tris.viscous_stress.assign(3 * d.tris.size(), 0.0f);
}

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

[[noreturn]] void raise_bad_triangle(const detail::EngineData& d, long t) {
  double j;
  detail::triangle_stress(d, t, j);
  std::ostringstream msg;
  msg << "fdem: step " << d.step << " (t = " << fmt(d.time) << " s): triangle " << t;
  if (std::isfinite(j)) {
    msg << " is inverted: Jacobian J = " << fmt(j) << " <= 0";
  } else {
    msg << " has a non-finite Jacobian J = " << j;
  }
  msg << " (nodes";
  for (int k = 0; k < 3; ++k) {
    const int n = d.tris.nodes[3 * t + k];
    msg << ' ' << n << " at (" << fmt(d.nodes.pos[2 * n]) << ", " << fmt(d.nodes.pos[2 * n + 1])
        << ")";
  }
  msg << "). The run is unstable: reduce dt (now " << fmt(d.dt)
      << " s), the loading rate or the penalties, or add damping.";
  throw NumericalError(msg.str());
}

[[noreturn]] void raise_bad_node(const detail::EngineData& d, long n) {
  std::ostringstream msg;
  msg << "fdem: step " << d.step << ": node " << n << " (mesh vertex " << d.nodes.vertex[n]
      << ") has a non-finite velocity or position (" << d.nodes.pos[2 * n] << ", "
      << d.nodes.pos[2 * n + 1] << "), velocity (" << d.nodes.vel[2 * n] << ", "
      << d.nodes.vel[2 * n + 1] << "). Reduce dt (now " << fmt(d.dt)
      << " s) or check the loads on that node.";
  throw NumericalError(msg.str());
}

/// Runs `change` on triangle t and books the change of its stored energy
/// (at the half step) in `term`.
template <class Change>
void book_triangle_change(detail::EngineData& d, std::size_t t, double detail::EnergyLedger::*term,
                          const Change& change) {
  const detail::Placement at = detail::half_step_placement(d);
  detail::book_change(
      d.energy, term, [&] { return detail::triangle_stored_energy(d, t, at); }, change);
}

/// Runs `change` on crack element c and books the change of its energy (at
/// the half step) as removed.
template <class Change>
void book_crack_change(detail::EngineData& d, std::size_t c, const Change& change) {
  const detail::Placement at = detail::half_step_placement(d);
  detail::book_change(
      d.energy, &detail::EnergyLedger::removed,
      [&] { return detail::crack_element_energy(d, c, at); }, change);
}

void check_index(std::size_t i, std::size_t n, const char* what) {
  if (i >= n)
    throw InputError(std::string("fdem: ") + what + " " + std::to_string(i) + " outside [0, " +
                     std::to_string(n) + ")");
}

}  // namespace

// --- Construction -----------------------------------------------------------

Engine::Engine(const ModelInput& in) : impl_(std::make_unique<Impl>()) {
  detail::validate_input(in);
  detail::check_simd_isa_request();  // resolves the vector kernels' set, serially
  auto& d = impl_->d;
  d.materials = in.materials;
  for (const Material& m : in.materials) {
    d.solids.push_back(solid_constants(m, in.plane));
    d.crack_laws.push_back(make_crack_constants(m));
  }
  d.threads = in.threads;
  d.damping = in.damping;
  d.mass_scaling = in.mass_scaling;
  d.gravity[0] = in.gravity_x;
  d.gravity[1] = in.gravity_y;
  detail::build_topology(in, d);
  detail::assign_strength_factors(d);
  detail::init_joint_friction(d);
  set_viscous_damping(d);
  detail::resolve_edges(in, d);
  detail::apply_boundary_conditions(in.boundary_conditions, d);
  // Crack elements start carrying the initial stress (the in-situ hand-off
  // must start in equilibrium with or without a fracture zone). Done before
  // the first step, so that triangles deactivated, stresses replaced or
  // boundary conditions changed after construction are accounted for.
  impl_->prestress_pending = !in.initial_stress.empty();
  if (in.contact.enabled) set_contact(in.contact);
  impl_->dt_safety = in.dt_safety;
  if (in.dt > 0) set_dt(in.dt);
  impl_->refresh();
}

Engine::~Engine() = default;
Engine::Engine(Engine&&) noexcept = default;
Engine& Engine::operator=(Engine&&) noexcept = default;

// --- Sizes -------------------------------------------------------------------

std::size_t Engine::n_nodes() const { return impl_->d.nodes.size(); }
std::size_t Engine::n_triangles() const { return impl_->d.tris.size(); }
std::size_t Engine::n_cracks() const { return impl_->d.cracks.size(); }
const std::vector<int>& Engine::node_vertex() const { return impl_->d.nodes.vertex; }

std::array<int, 3> Engine::triangle_nodes(std::size_t t) const {
  check_index(t, n_triangles(), "triangle");
  const int* n = &impl_->d.tris.nodes[3 * t];
  return {n[0], n[1], n[2]};
}

std::array<int, 4> Engine::crack_nodes(std::size_t c) const {
  check_index(c, n_cracks(), "crack element");
  const int* n = &impl_->d.cracks.nodes[4 * c];
  return {n[0], n[1], n[2], n[3]};
}

std::array<int, 2> Engine::crack_triangles(std::size_t c) const {
  check_index(c, n_cracks(), "crack element");
  return {impl_->d.crack_triangle(c, 0), impl_->d.crack_triangle(c, 1)};
}

// --- Time step -----------------------------------------------------------------

/// Brings masses, loads and the stability limit up to date after a stage
/// change. An automatic dt follows the new limit; an explicit one is checked
/// against it before the next step (step()), so that set_dt can still lower
/// it first.
void Engine::Impl::refresh() {
  if (d.masses_dirty) detail::refresh_nodes(d);
  if (critical_dt >= 0) return;
  critical_dt = detail::critical_dt(d);
  if (d.contact_on) {  // the contact penalty adds its frequency to the model's
    const double omega = 2.0 / critical_dt, w2 = detail::contact_omega2(d);
    // Both terms as effective frequencies, damping included: the model's
    // limit is already reduced for its damping; the contact's own ratio and
    // the local damping (which acts on contact forces too) raise its
    // frequency by damping_stiffening.
    const double f =
        w2 > 0 ? detail::damping_stiffening(d, std::sqrt(w2), d.contact.settings.damping_ratio)
               : 1.0;
    critical_dt = 2.0 / std::sqrt(omega * omega + w2 * f * f);
  }
  if (auto_dt) d.dt = dt_safety * critical_dt;
}

double Engine::critical_dt() const {
  impl_->refresh();
  return impl_->critical_dt;
}

double Engine::stable_dt() const { return impl_->dt_safety * critical_dt(); }
double Engine::dt() const { return impl_->d.dt; }

void Engine::set_dt(double dt, DtCheck check) {
  if (!(dt > 0)) throw InputError("fdem: dt = " + fmt(dt) + " s must be > 0");
  const double limit = critical_dt();
  if (dt > limit && check == DtCheck::kRefuseAboveLimit)
    throw InputError("fdem: dt = " + fmt(dt) + " s exceeds the stability limit " + fmt(limit) +
                     " s of this mesh and its penalties (the default uses " +
                     fmt(impl_->dt_safety) + " of it, " + fmt(stable_dt()) +
                     " s); choose dt <= " + fmt(limit) + " s or force it with DtCheck::kForce");
  impl_->d.dt = dt;
  impl_->auto_dt = false;
  impl_->forced_dt = check == DtCheck::kForce;
}

// --- Running -----------------------------------------------------------------------

void Engine::step() {
  auto& d = impl_->d;
  impl_->refresh();
  if (!impl_->auto_dt && !impl_->forced_dt && d.dt > impl_->critical_dt)
    throw InputError("fdem: after a stage change the stability limit is " +
                     fmt(impl_->critical_dt) + " s, below the dt = " + fmt(d.dt) +
                     " s set earlier; set a smaller dt (or force it)");
  if (impl_->prestress_pending) {
    impl_->prestress_clipped = detail::prestress_cracks(d);
    impl_->prestress_pending = false;
  }
  if (!d.energy.started) detail::start_ledger(d);
  const double t0 = omp_get_wtime();
  const long bad_tri = detail::triangle_forces(d);
  const double t1 = omp_get_wtime();
  impl_->times.triangles += t1 - t0;
  if (bad_tri >= 0) raise_bad_triangle(d, bad_tri);
  const long n_broken = detail::crack_forces(d);
  detail::book_joint_friction(d);  // the ledger only: forces unchanged
  double t2 = omp_get_wtime();
  impl_->times.cracks += t2 - t1;
  if (d.contact_on) {                             // one branch per step while contact is off
    if (n_broken > 0) detail::contact_breaks(d);  // a local update, not a new detection
    detail::contact_forces(d);
    const double t3 = omp_get_wtime();
    impl_->times.contact += t3 - t2;
    t2 = t3;
  }
  const long bad_node = detail::node_update(d);
  d.energy.last_dt = d.dt;
  ++d.step;
  d.time += d.dt;
  if (bad_node >= 0) raise_bad_node(d, bad_node);
  detail::contact_nodes_moved(d.contact, d.fastest_speed * d.dt);
  // After the step, at its velocities; a reset moves the nodes back.
  if (d.damping.kinetic && detail::kinetic_damping(d)) detail::contact_drift_unknown(d.contact);
  impl_->times.nodes += omp_get_wtime() - t2;
  check_reversal();
}

/// Above the stability limit the stiffest mode grows by a factor g > 1 per
/// step with alternating sign: v_new = -g v_old. A velocity correlation
/// sum v_old.v_new / sum v_old^2 below -1.1 three steps in a row is that and
/// nothing physical (a stable scheme keeps it >= -1).
void Engine::check_reversal() {
  auto& im = *impl_;
  const double dot = im.d.reversal[0], kin = im.d.reversal[1];
  const bool growing = kin > 0 && dot < -1.1 * kin;
  im.reversals = growing ? im.reversals + 1 : 0;
  if (im.reversals < 3) return;
  std::ostringstream msg;
  msg << "fdem: step " << im.d.step << ": unstable time integration: the free nodes' velocities "
      << "reversed and grew by a factor " << fmt(-dot / kin) << " (sum v_old.v_new / sum v_old^2)"
      << " for 3 steps in a row. dt = " << fmt(im.d.dt) << " s against the stability limit "
      << fmt(im.critical_dt) << " s; reduce dt (do not force it above the limit).";
  throw NumericalError(msg.str());
}

void Engine::run(long n_steps) {
  for (long i = 0; i < n_steps; ++i) step();
}

EquilibriumResult Engine::run_to_equilibrium(const EquilibriumCriteria& c) {
  if (c.check_interval <= 0 || c.max_steps < 0)
    throw InputError("fdem: equilibrium check interval must be > 0 and max steps >= 0");
  EquilibriumResult r;
  double peak = kinetic_energy();
  while (r.steps < c.max_steps) {
    const long n = std::min(c.check_interval, c.max_steps - r.steps);
    run(n);
    r.steps += n;
    const double ke = kinetic_energy();
    peak = std::max(peak, ke);
    r.kinetic_ratio = peak > 0 ? ke / peak : 0.0;
    r.force_ratio = unbalanced_force_ratio();
    if (r.force_ratio <= c.force_ratio && r.kinetic_ratio <= c.kinetic_ratio) {
      r.converged = true;
      break;
    }
  }
  return r;
}

long Engine::step_count() const { return impl_->d.step; }
double Engine::time() const { return impl_->d.time; }

// --- Stage controls ------------------------------------------------------------------

void Engine::set_stiffness_factor(std::size_t t, double alpha) {
  check_index(t, n_triangles(), "triangle");
  if (!(alpha >= 0 && alpha <= 1e3))
    throw InputError("fdem: stiffness factor " + fmt(alpha) + " for triangle " + std::to_string(t) +
                     " must lie in [0, 1000]");
  auto& d = impl_->d;
  book_triangle_change(d, t, &detail::EnergyLedger::softening, [&] { d.tris.alpha[t] = alpha; });
  impl_->stiffness_changed();
}

double Engine::stiffness_factor(std::size_t t) const {
  check_index(t, n_triangles(), "triangle");
  return impl_->d.tris.alpha[t];
}

void Engine::set_active(std::size_t t, bool on, ActivationReference ref) {
  check_index(t, n_triangles(), "triangle");
  auto& d = impl_->d;
  // Its strain energy and its contacts go (or its strain energy comes); its
  // nodes' kinetic energy and its crack elements follow at the refresh. The
  // contacts count while the triangle is active and about to go: once
  // inactive it has none (they leave at the next detection).
  const detail::Placement at = detail::half_step_placement(d);
  const auto stored = [&] {
    double e = detail::triangle_stored_energy(d, t, at);
    if (!on && d.tris.active[t]) e += detail::contact_energy_of_triangle(d, int(t), at);
    return e;
  };
  detail::book_change(d.energy, &detail::EnergyLedger::removed, stored, [&] {
    if (on && ref == ActivationReference::kCurrent) {
      // Stress-free in the shape it has now: neither strain nor the initial
      // stress it carried as part of a softened core counts any more.
      detail::set_reference_to_current(d, t);
      if (!d.tris.sigma0.empty())
        for (int k = 0; k < 3; ++k) d.tris.sigma0[3 * t + k] = 0.0;
    }
    d.tris.active[t] = on ? 1 : 0;
    if (!d.tris.viscous_stress.empty())
      for (int k = 0; k < 3; ++k) d.tris.viscous_stress[3 * t + k] = 0.0f;
  });
  d.masses_dirty = true;
  d.contact.topology_dirty = d.contact.dirty = true;  // free surfaces change
  impl_->critical_dt = -1;
}

bool Engine::active(std::size_t t) const {
  check_index(t, n_triangles(), "triangle");
  return impl_->d.tris.active[t] != 0;
}

void Engine::set_boundary_conditions(const std::vector<BoundaryCondition>& bcs) {
  for (const auto& bc : bcs) {
    bool found = false;
    for (const auto& e : impl_->d.edges) found = found || e.tag == bc.tag;
    if (!found)
      throw InputError("fdem: boundary condition for tag " + std::to_string(bc.tag) +
                       " but no edge carries it");
  }
  detail::apply_boundary_conditions(bcs, impl_->d);
}

void Engine::set_gravity(double gx, double gy) {
  impl_->d.gravity[0] = gx;
  impl_->d.gravity[1] = gy;
  impl_->d.masses_dirty = true;
}

void Engine::set_damping(const DampingSettings& damping) {
  if (!(damping.local >= 0 && damping.local < 1) || !(damping.mass_proportional >= 0))
    throw InputError("fdem: local damping must lie in [0, 1) and mass-proportional be >= 0");
  // Switched on: the peak test starts afresh (its memory may be stale).
  if (damping.kinetic && !impl_->d.damping.kinetic) {
    impl_->d.kinetic_damping.previous = 0;
    impl_->d.kinetic_damping.rising = false;
  }
  impl_->d.damping = damping;
  impl_->stiffness_changed();  // local and mass damping lower the limit
}

void Engine::set_mass_scaling(const MassScaling& scaling) {
  if (!(scaling.dt >= 0) || !std::isfinite(scaling.dt))
    throw InputError("fdem: mass scaling dt = " + fmt(scaling.dt) +
                     " s must be >= 0 (0 selects the least constrained node's own limit)");
  auto& d = impl_->d;
  d.mass_scaling = scaling;
  d.scaled_dt = 0;  // resolved again at the next refresh (which also drops the factors)
  d.masses_dirty = true;
  impl_->critical_dt = -1;
}

MassScalingReport Engine::mass_scaling_report() const {
  impl_->refresh();
  const auto& d = impl_->d;
  MassScalingReport r;
  r.enabled = d.mass_scaling.enabled;
  if (!r.enabled) return r;
  r.target_dt = d.scaled_dt / std::sqrt(1.0 + d.damping.local);
  double scaled = 0, real = 0;
  for (std::size_t t = 0; t < d.tris.size(); ++t) {
    if (!d.tris.active[t]) continue;
    const double f = d.tris.density_factor(t),
                 m = d.solids[d.tris.material[t]].rho * d.tris.area0[t];
    r.max_factor = std::max(r.max_factor, f);
    scaled += f * m;
    real += m;
    if (f > 1.0) ++r.scaled_triangles;
  }
  r.mass_ratio = real > 0 ? scaled / real : 1.0;
  return r;
}

void Engine::set_crack_material(std::size_t c, int material) {
  check_index(c, n_cracks(), "crack element");
  check_index(static_cast<std::size_t>(material), impl_->d.materials.size(), "material");
  auto& d = impl_->d;
  book_crack_change(d, c, [&] {
    d.cracks.material[c] = static_cast<std::uint16_t>(material);
    detail::assign_strength_factor(d, c);  // the new material's strengths (and its factor)
    detail::update_joint_list(d, c);
  });
  impl_->stiffness_changed();
}

void Engine::rejoin_crack(std::size_t c, int material) {
  set_crack_material(c, material);
  auto& d = impl_->d;
  book_crack_change(d, c, [&] {
    auto& cr = d.cracks;
    if (cr.offset.empty()) cr.offset.assign(6 * cr.size(), 0.0);
    double opening[6];
    detail::crack_point_openings(d, c, opening);
    for (int i = 0; i < 3; ++i)
      detail::store_offsets(opening[2 * i], opening[2 * i + 1], 0.0, 0.0,
                            &cr.offset[6 * c + 2 * i]);
    for (int k = 0; k < 3; ++k) cr.damage[3 * c + k] = 0.0;
    if (cr.state[c] == std::uint8_t(CrackState::kBroken))
      --d.broken_by_mode[detail::broken_mode_entry(cr.mode[c])];
    cr.state[c] = std::uint8_t(CrackState::kIntact);
    cr.mode[c] = std::uint8_t(FailureMode::kNone);
    cr.broken_step[c] = -1;
  });
  d.contact.topology_dirty = d.contact.dirty = true;
}

int Engine::rejoin_crack_keeping_traction(std::size_t c, int material) {
  check_index(c, n_cracks(), "crack element");
  auto& d = impl_->d;
  double stresses[6];
  detail::crack_point_stresses(d, c, stresses);  // under the present law, before the switch
  rejoin_crack(c, material);
  int clipped = 0;
  book_crack_change(d, c, [&] { clipped = detail::carry_point_stresses(d, c, stresses); });
  return clipped;
}

void Engine::set_initial_stress(std::size_t t, const std::array<double, 3>& stress) {
  check_index(t, n_triangles(), "triangle");
  auto& d = impl_->d;
  book_triangle_change(d, t, &detail::EnergyLedger::removed, [&] {
    auto& s0 = d.tris.sigma0;
    if (s0.empty()) s0.assign(3 * n_triangles(), 0.0);
    for (int k = 0; k < 3; ++k) s0[3 * t + k] = stress[k];
  });
}

void Engine::set_contact(const ContactSettings& contact) {
  if (!(contact.penalty >= 0) || !(contact.buffer >= 0) || !(contact.damping_ratio >= 0) ||
      !(contact.damping_ratio <= 1))
    throw InputError(
        "fdem: contact penalty and buffer must be >= 0 (0 = default) and the "
        "damping ratio in [0, 1]");
  auto& d = impl_->d;
  const detail::Placement at = detail::half_step_placement(d);
  detail::book_change(
      d.energy, &detail::EnergyLedger::removed, [&] { return detail::contact_energy(d, at); },
      [&] {
        d.contact.settings = contact;
        d.contact_on = contact.enabled;
        if (contact.enabled) detail::contact_setup(d);
      });
  impl_->stiffness_changed();  // contact joins the limit and the scaled frequencies
}

bool Engine::contact_active() const {
  return impl_->d.contact_on && !impl_->d.contact.pairs.empty();
}

void check_environment() { detail::check_simd_isa_request(); }

ContactCounters Engine::contact_counters() const {
  const auto& c = impl_->d.contact;
  ContactCounters r;
  r.enabled = impl_->d.contact_on;
  r.candidates = static_cast<long>(c.candidates.size());
  r.pairs = static_cast<long>(c.pairs.size());
  r.touching = c.touching;
  r.detections = c.detections;
  r.steps_with_pairs = c.steps_with_pairs;
  r.steps_skipped = c.steps_skipped;
  r.updates = c.updates;
  r.kernel = detail::simd_isa_name();
  return r;
}

void Engine::set_threads(int n_threads) {
  if (n_threads < 0) throw InputError("fdem: thread count must be >= 0 (0 = OpenMP default)");
  impl_->d.threads = n_threads;
}

int Engine::threads() const { return detail::thread_count(impl_->d.threads); }

// --- State -----------------------------------------------------------------------------

const std::vector<double>& Engine::positions() const { return impl_->d.nodes.pos; }
const std::vector<double>& Engine::velocities() const { return impl_->d.nodes.vel; }

const std::vector<float>& Engine::node_mass() const {
  if (impl_->d.masses_dirty) detail::refresh_nodes(impl_->d);
  return impl_->d.nodes.mass;
}

void Engine::set_node_state(std::size_t node, double x, double y, double vx, double vy) {
  check_index(node, n_nodes(), "node");
  auto& d = impl_->d;
  detail::book_change(
      d.energy, &detail::EnergyLedger::removed, [&] { return detail::node_energy(d, node); },
      [&] {
        d.nodes.pos[2 * node] = x;
        d.nodes.pos[2 * node + 1] = y;
        d.nodes.vel[2 * node] = vx;
        d.nodes.vel[2 * node + 1] = vy;
      });
  d.contact.dirty = true;  // a jump the drift check does not bound
}

std::array<double, 2> Engine::node_force(std::size_t node) const {
  check_index(node, n_nodes(), "node");
  std::array<double, 2> f;
  detail::node_force(impl_->d, node, f[0], f[1]);
  return f;
}

std::array<double, 2> Engine::displacement(std::size_t node) const {
  check_index(node, n_nodes(), "node");
  const auto& n = impl_->d.nodes;
  return {n.pos[2 * node] - n.mesh_position(node, 0),
          n.pos[2 * node + 1] - n.mesh_position(node, 1)};
}

std::array<double, 3> Engine::triangle_stress(std::size_t t) const {
  check_index(t, n_triangles(), "triangle");
  double j;
  return detail::triangle_stress(impl_->d, t, j);
}

double Engine::triangle_stress_zz(std::size_t t, double sigma0_zz) const {
  check_index(t, n_triangles(), "triangle");
  return detail::triangle_stress_zz(impl_->d, t, sigma0_zz);
}

double Engine::crack_damage(std::size_t c) const {
  check_index(c, n_cracks(), "crack element");
  const float* d = &impl_->d.cracks.damage[3 * c];
  return std::max({d[0], d[1], d[2]});
}

double Engine::crack_strength_factor(std::size_t c) const {
  check_index(c, n_cracks(), "crack element");
  const auto& k = impl_->d.cracks.strength;
  return k.empty() ? 1.0 : k[c];
}

CrackDisplacement Engine::crack_displacement(std::size_t c) const {
  check_index(c, n_cracks(), "crack element");
  const auto& d = impl_->d;
  double os[6];
  CrackDisplacement r;
  r.length = detail::crack_point_openings(d, c, os);
  for (int i = 0; i < 3; ++i) {
    r.opening[i] = os[2 * i];
    r.slip[i] = os[2 * i + 1];
  }
  detail::subtract_offsets(d, c, os);
  for (int i = 0; i < 3; ++i) {
    r.law_opening[i] = os[2 * i];
    r.law_slip[i] = os[2 * i + 1];
  }
  return r;
}

CrackState Engine::crack_state(std::size_t c) const {
  check_index(c, n_cracks(), "crack element");
  return CrackState(impl_->d.cracks.state[c]);
}

FailureMode Engine::crack_mode(std::size_t c) const {
  check_index(c, n_cracks(), "crack element");
  return FailureMode(impl_->d.cracks.mode[c]);
}

long Engine::crack_prestress_clipped() const { return impl_->prestress_clipped; }

long Engine::crack_broken_step(std::size_t c) const {
  check_index(c, n_cracks(), "crack element");
  return impl_->d.cracks.broken_step[c];
}

}  // namespace rockfdem::fdem
