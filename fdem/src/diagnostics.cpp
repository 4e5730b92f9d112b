// Global figures of the Engine. Every sum is a fixed-block sum (parallel.hpp)
// so the figures, like the state, do not depend on the thread count. None of
// them runs inside the time loop: they are computed when asked for.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "crack_elements.hpp"
#include "energy.hpp"
#include "engine_impl.hpp"
#include "node_update.hpp"
#include "parallel.hpp"
#include "rockfdem/fdem/bits_hash.hpp"
#include "triangle_force.hpp"

namespace rockfdem::fdem {

double Engine::kinetic_energy() const { return detail::kinetic_energy(impl_->d); }

long Engine::kinetic_damping_resets() const { return impl_->d.kinetic_damping.resets; }

double Engine::strain_energy() const {
  const auto& d = impl_->d;
  return detail::block_sum(static_cast<long>(d.tris.size()), d.threads,
                           [&](long t) { return detail::triangle_strain_energy(d, t); });
}

double Engine::crack_energy() const {
  const auto& d = impl_->d;
  return detail::block_sum(static_cast<long>(d.cracks.size()), d.threads,
                           [&](long c) { return detail::crack_element_energy(d, c); });
}

double Engine::unbalanced_force_ratio() const {
  const auto& d = impl_->d;
  const long nn = static_cast<long>(d.nodes.size());
  // A component counts only when free: a constrained one carries a reaction.
  auto free_x = [&](long i) {
    const int b = d.nodes.bc[i];
    return d.nodes.inv_mass[i] > 0 && (b < 0 || d.bc_records[b].x == Constraint::kFree);
  };
  auto free_y = [&](long i) {
    const int b = d.nodes.bc[i];
    return d.nodes.inv_mass[i] > 0 && (b < 0 || d.bc_records[b].y == Constraint::kFree);
  };
  const double net = detail::block_sum(nn, d.threads, [&](long i) {
    double fx, fy;
    detail::node_force(d, i, fx, fy);
    return (free_x(i) ? std::fabs(fx) : 0.0) + (free_y(i) ? std::fabs(fy) : 0.0);
  });
  const double gross = detail::block_sum(nn, d.threads, [&](long i) {
    const bool fx_on = free_x(i), fy_on = free_y(i);
    double s = (fx_on ? std::fabs(d.nodes.fext[2 * i]) : 0.0) +
               (fy_on ? std::fabs(d.nodes.fext[2 * i + 1]) : 0.0);
    for (int k = d.nodes.slot_start[i]; k < d.nodes.slot_start[i + 1]; ++k) {
      const int sl = d.nodes.slot_index[k];
      s += (fx_on ? std::fabs(d.slots[2 * sl]) : 0.0) +
           (fy_on ? std::fabs(d.slots[2 * sl + 1]) : 0.0);
    }
    return s;
  });
  return gross > 0 ? net / gross : 0.0;
}

BrokenCounts Engine::broken_counts() const {
  const auto& c = impl_->d.cracks;
  BrokenCounts b;
  for (std::size_t e = 0; e < c.size(); ++e) {
    if (c.state[e] != std::uint8_t(CrackState::kBroken)) continue;
    switch (FailureMode(c.mode[e])) {
      case FailureMode::kModeI:
        ++b.mode_I;
        break;
      case FailureMode::kModeII:
        ++b.mode_II;
        break;
      default:
        ++b.mixed;
        break;
    }
  }
  return b;
}

std::array<double, 2> Engine::boundary_force(int tag) const {
  const auto& d = impl_->d;
  double sx = 0, sy = 0;
  for (const auto& tn : d.tag_nodes) {
    if (tn.tag != tag) continue;
    for (int i : tn.nodes) {
      // The node barely accelerates, so the condition balances the body's
      // force on it: f_bc = -(f_internal + f_external), per constrained component.
      double fx, fy;
      detail::node_force(d, i, fx, fy);
      const auto& r = d.bc_records[d.nodes.bc[i]];
      if (r.x != Constraint::kFree) sx -= fx;
      if (r.y != Constraint::kFree) sy -= fy;
    }
  }
  return {sx, sy};
}

std::string Engine::state_hash() const { return bits_hash(impl_->d.nodes.pos); }

PhaseTimes Engine::phase_times() const { return impl_->times; }

namespace {

/// Contact arrays: per-triangle edge topology and per-node labels (when
/// enabled), plus what the last detection holds.
template <class Bytes>
std::size_t contact_bytes(const detail::ContactData& c, Bytes b) {
  const auto& s = c.breaks;
  return b(c.edge_nbr) + b(c.edge_crack) + b(c.vertex_tri_start) + b(c.vertex_tri) +
         b(c.vertex_crack_start) + b(c.vertex_crack) + b(c.component) + b(c.candidates) +
         b(c.boxes) + b(c.watch_nodes) + b(c.detect_pos) + b(c.pairs) + b(c.old_pairs) +
         b(c.friction) + b(c.old_friction) + b(c.pair_force) + b(c.gather_tri) + b(c.gather_start) +
         b(c.gather_entry) + b(c.grid.cell) + b(c.grid.cell_start) + b(c.grid.items) +
         b(c.grid.count) + b(c.grid.offset) + b(c.grid.found) + b(c.energy_partial) + b(s.cracks) +
         b(s.tris) + b(s.vertices) + b(s.ints) + b(s.merged) + b(s.boxes) + b(s.trial) +
         b(s.found) + b(s.gather_index) + b(c.narrow.tris) + b(c.narrow.rows);
}

}  // namespace

std::size_t Engine::memory_bytes() const {
  const auto& d = impl_->d;
  auto b = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  const auto& n = d.nodes;
  const auto& t = d.tris;
  const auto& c = d.cracks;
  return b(n.pos) + b(n.vel) + b(n.mesh_pos) + b(n.mass) + b(n.inv_mass) + b(n.fext) + b(n.bc) +
         b(n.vertex) + b(n.slot_start) + b(n.slot_index) + b(t.nodes) + b(t.ref_inv) + b(t.area0) +
         b(t.eta) + b(t.alpha) + b(t.sigma0) + b(t.viscous_stress) + b(t.material) + b(t.active) +
         b(c.nodes) + b(c.tri) + b(c.damage) + b(c.material) + b(c.state) + b(c.mode) +
         b(c.active) + b(c.broken_step) + b(c.offset) + b(c.joints) + b(c.joint_force) +
         b(d.slots) + b(d.block_partial) + b(d.energy_partial) + b(d.vertex_nodes) +
         b(d.vertex_node_start) + contact_bytes(d.contact, b);
}

}  // namespace rockfdem::fdem
