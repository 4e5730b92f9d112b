// Global figures of the Engine. Every sum is a fixed-block sum (parallel.hpp)
// so the figures, like the state, do not depend on the thread count. None of
// them runs inside the time loop: they are computed when asked for.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

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
  auto free = [&](long i, bool& x, bool& y) {
    const long b = d.nodes.bc(i);
    x = d.nodes.mass[i] > 0 && (b < 0 || d.bc_records[b].x == Constraint::kFree);
    y = d.nodes.mass[i] > 0 && (b < 0 || d.bc_records[b].y == Constraint::kFree);
  };
  const double net = detail::block_sum(nn, d.threads, [&](long i) {
    bool fx_on, fy_on;
    free(i, fx_on, fy_on);
    double fx, fy;
    detail::node_force(d, i, fx, fy);
    return (fx_on ? std::fabs(fx) : 0.0) + (fy_on ? std::fabs(fy) : 0.0);
  });
  const double gross = detail::block_sum(nn, d.threads, [&](long i) {
    bool fx_on, fy_on;
    free(i, fx_on, fy_on);
    double s = (fx_on ? std::fabs(detail::dead_load(d.nodes, i, 0)) : 0.0) +
               (fy_on ? std::fabs(detail::dead_load(d.nodes, i, 1)) : 0.0);
    for (int k = d.nodes.slot_start[i]; k < d.nodes.slot_start[i + 1]; ++k) {
      const int sl = detail::entry_slot(d.nodes.slot_index[k]);
      s += (fx_on ? std::fabs(d.slots[2 * sl]) : 0.0) +
           (fy_on ? std::fabs(d.slots[2 * sl + 1]) : 0.0);
    }
    return s;
  });
  return gross > 0 ? net / gross : 0.0;
}

BrokenCounts Engine::broken_counts() const {
  const auto& b = impl_->d.broken_by_mode;
  return {b[0], b[1], b[2]};
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
      const auto& r = d.bc_records[d.nodes.bc(i)];
      if (r.x != Constraint::kFree) sx -= fx;
      if (r.y != Constraint::kFree) sy -= fy;
    }
  }
  return {sx, sy};
}

std::string Engine::state_hash() const { return bits_hash(impl_->d.nodes.pos); }

PhaseTimes Engine::phase_times() const { return impl_->times; }

namespace {

/// Appends arrays `v` under "record.name", the names listed in `names`
/// separated by spaces, in the order of `v`.
template <class... V>
void add_parts(std::vector<MemoryPart>& parts, const char* record, const char* names,
               const V&... v) {
  std::istringstream words(names);
  auto add = [&](std::size_t bytes) {
    std::string name;
    words >> name;
    parts.push_back({std::string(record) + "." + name, bytes});
  };
  (add(v.capacity() * sizeof(typename V::value_type)), ...);
}

/// Every array of the engine: nodes, elements, force slots, contact's
/// per-triangle topology and per-node labels (when enabled), what the last
/// detection holds and the scratch it reuses.
std::vector<MemoryPart> memory_parts(const detail::EngineData& d) {
  std::vector<MemoryPart> p;
  const auto& n = d.nodes;
  add_parts(p, "nodes",
            "pos vel vertex_pos mass fext_node fext bc_node vertex slot_start slot_index", n.pos,
            n.vel, n.vertex_pos, n.mass, n.fext.node, n.fext.force, n.bc_node, n.vertex,
            n.slot_start, n.slot_index);
  const auto& t = d.tris;
  add_parts(p, "tris",
            "nodes ref_inv area0 eta alpha sigma0 viscous_stress mass_scale material active",
            t.nodes, t.ref_inv, t.area0, t.eta, t.alpha, t.sigma0, t.viscous_stress, t.mass_scale,
            t.material, t.active);
  const auto& c = d.cracks;
  add_parts(p, "cracks",
            "nodes damage material state mode active broken_step broke_in_block offset strength "
            "joints joint_force",
            c.nodes, c.damage, c.material, c.state, c.mode, c.active, c.broken_step,
            c.broke_in_block, c.offset, c.strength, c.joints, c.joint_force);
  add_parts(p, "engine", "slots block_partial energy_partial vertex_nodes vertex_node_start",
            d.slots, d.block_partial, d.energy_partial, d.vertex_nodes, d.vertex_node_start);
  const auto& k = d.contact;
  add_parts(p, "contact",
            "candidates boxes watch_nodes detect_shift pairs appended_order friction pair_force "
            "gather_tri gather_start gather_entry extra_head extra_next appended_rows "
            "entry_row energy_partial",
            k.candidates, k.boxes, k.watch_nodes, k.detect_shift, k.pairs, k.appended_order,
            k.friction, k.pair_force, k.gather_tri, k.gather_start, k.gather_entry, k.extra_head,
            k.extra_next, k.appended_rows, k.entry_row, k.energy_partial);
  const auto& g = k.grid;
  add_parts(p, "contact.grid", "cell cell_start items count offset found", g.cell, g.cell_start,
            g.items, g.count, g.offset, g.found);
  const auto& b = k.breaks;
  add_parts(p, "contact.breaks", "cracks tris vertices ints merged trial found gather_index",
            b.cracks, b.tris, b.vertices, b.ints, b.merged, b.trial, b.found, b.gather_index);
  add_parts(p, "contact.narrow", "tris boxes", k.narrow.tris, k.narrow.boxes);
  return p;
}

}  // namespace

std::vector<MemoryPart> Engine::memory_breakdown() const { return memory_parts(impl_->d); }

std::size_t Engine::memory_bytes() const {
  std::size_t sum = 0;
  for (const MemoryPart& p : memory_breakdown()) sum += p.bytes;
  return sum;
}

}  // namespace rockfdem::fdem
