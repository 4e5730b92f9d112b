// Node loop of the explicit step.
//
// Local (Cundall) damping removes alpha |f| against the velocity in each
// component: it damps without the rate dependence of viscous damping, which
// is what quasi-static stages want. Mass-proportional damping c m v is the
// classic alternative. Neither is applied to constrained components.
#include "node_update.hpp"

#include <algorithm>
#include <cmath>

#include "energy.hpp"
#include "mass_scaling.hpp"
#include "parallel.hpp"

namespace rockfdem::fdem::detail {
namespace {

/// Partial sums per node block: reversal (2), external work, damping,
/// absorbing dashpots, kinetic energy at the new velocities; then the
/// largest squared speed.
constexpr int kNodeSums = 7;

/// -1, 0 or +1 without a branch: a vibrating body's velocities change sign
/// at random, which a branch predictor cannot follow (the compiler turned
/// double(v > 0) - double(v < 0) into one). A NaN gives 0, as that did.
inline double sign(double v) {
  static constexpr double kSign[3] = {-1.0, 0.0, 1.0};
  return kSign[1 + int(v > 0.0) - int(v < 0.0)];
}

/// Sum over node i's active triangles of rho f(t) A0 / 3.
template <class Factor>
double corner_sum(const EngineData& d, long i, Factor f) {
  const long tri_slots = static_cast<long>(d.crack_slot0());
  const Nodes& n = d.nodes;
  const Triangles& tr = d.tris;
  double m = 0;
  for (int k = n.slot_start[i]; k < n.slot_start[i + 1]; ++k) {
    const int s = entry_slot(n.slot_index[k]);
    if (s >= tri_slots) break;  // slots are sorted: triangles come first
    const int t = s / 3;
    if (tr.active[t]) m += d.solids[tr.material[t]].rho * f(t) * tr.area0[t] / 3.0;
  }
  return m;
}

/// Mass of node i from its active triangles with density factors `scale`
/// (one per triangle; empty: the true masses).
float corner_mass(const EngineData& d, long i, const std::vector<float>& scale) {
  return static_cast<float>(
      corner_sum(d, i, [&](int t) { return scale.empty() ? 1.0 : double(scale[t]); }));
}

/// The mass gravity pulls on at node i: a softened triangle (stiffness
/// factor alpha < 1, the excavation's core) carries alpha of its weight, as
/// it carries alpha of its in-situ stress, so that a softened core stays in
/// equilibrium with its own weight (the implicit stage gives it alpha of its
/// body force too). A stiffened one (a bolt strip, alpha > 1) keeps its
/// true weight. Mass scaling never changes it.
double weight_mass(const EngineData& d, long i) {
  return corner_sum(d, i, [&](int t) { return std::min(double(d.tris.alpha[t]), 1.0); });
}

/// A change of density factors keeps each node's momentum, m_old v_old =
/// m_new v_new (m_old: the old factors on the current activity), so that
/// rescaling never adds kinetic energy; the energy it takes out is booked
/// with the stage change (refresh_nodes).
void keep_momentum(EngineData& d, const std::vector<float>& old_scale) {
  Nodes& n = d.nodes;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const double m_old = corner_mass(d, long(i), old_scale), m_new = n.mass[i];  // as stored
    if (!(m_old > 0 && m_new > 0) || m_old == m_new) continue;
    n.vel[2 * i] *= m_old / m_new;
    n.vel[2 * i + 1] *= m_old / m_new;
  }
}

/// Gravity acts on the true masses, whatever the scaling of the inertia,
/// times the softening of each triangle (weight_mass): a force on every
/// node. Without gravity only the nodes of loaded boundaries carry one.
void refresh_external_forces(EngineData& d) {
  DeadLoads& f = d.nodes.fext;
  const bool gravity = d.gravity[0] != 0.0 || d.gravity[1] != 0.0;
  d.dead_loads = gravity || !d.loads.empty();
  f = DeadLoads{};  // no arrays of zeros: an empty `force` reads as zero
  if (!d.dead_loads) return;
  f.dense = gravity;
  if (gravity) {
    f.force.resize(2 * d.nodes.size());
    for (std::size_t i = 0; i < d.nodes.size(); ++i) {
      const double m = weight_mass(d, long(i));
      f.force[2 * i] = m * d.gravity[0];
      f.force[2 * i + 1] = m * d.gravity[1];
    }
  } else {
    for (const NodalLoad& l : d.loads) f.node.push_back(l.node);
    std::sort(f.node.begin(), f.node.end());
    f.node.erase(std::unique(f.node.begin(), f.node.end()), f.node.end());
    f.node.shrink_to_fit();
    f.none_x = 0.0 * d.gravity[0];
    f.none_y = 0.0 * d.gravity[1];
    f.force.resize(2 * f.node.size());
    for (std::size_t k = 0; k < f.node.size(); ++k) {
      f.force[2 * k] = f.none_x;
      f.force[2 * k + 1] = f.none_y;
    }
  }
  for (const NodalLoad& l : d.loads) {  // in their order, as they always were added
    const long k = f.find(l.node);
    f.force[2 * k] += l.fx;
    f.force[2 * k + 1] += l.fy;
  }
}

/// Crack elements act only between two active triangles; an element that
/// stops acting keeps zero forces in its slots.
void refresh_crack_activity(EngineData& d) {
  Cracks& c = d.cracks;
  const std::size_t slot0 = d.crack_slot0();
  for (std::size_t e = 0; e < c.size(); ++e) {
    const bool on = d.tris.active[d.crack_triangle(e, 0)] && d.tris.active[d.crack_triangle(e, 1)];
    c.active[e] = on;
    if (!on)
      for (int k = 0; k < 4; ++k) d.slots[2 * (slot0 + 2 * e) + k] = 0.0;
  }
  for (std::size_t t = 0; t < d.tris.size(); ++t)
    if (!d.tris.active[t])
      for (int k = 0; k < 6; ++k) d.slots[6 * t + k] = 0.0;
}

}  // namespace

void refresh_masses(EngineData& d) {
  const long nn = static_cast<long>(d.nodes.size());
  Nodes& n = d.nodes;
#pragma omp parallel for schedule(static) num_threads(thread_count(d.threads))
  for (long i = 0; i < nn; ++i) {
    const float m = corner_mass(d, i, d.tris.mass_scale);
    n.mass[i] = m;
    if (m == 0) n.vel[2 * i] = n.vel[2 * i + 1] = 0.0;
  }
}

void refresh_nodes(EngineData& d) {
  // Masses and crack activity change the kinetic and crack energies without
  // work (a stage control): the energy ledger books the difference. With
  // mass scaling the velocities change too (keep_momentum), and with them
  // the half-step placement of the strain and contact energies: then the
  // whole stored energy is compared.
  const bool scaled = d.mass_scaling.enabled || !d.tris.mass_scale.empty();
  const auto energy = [&] { return scaled ? stored_energy(d) : kinetic_and_crack_energy(d); };
  book_change(d.energy, &EnergyLedger::removed, energy, [&] {
    // Crack activity first: the mass scaling's stability bound reads it.
    refresh_crack_activity(d);
    const std::vector<float> old_scale = d.tris.mass_scale;  // empty unless scaled
    if (d.mass_scaling.enabled) {
      scale_masses(d);  // ends with refresh_masses
    } else {
      d.tris.mass_scale.clear();
      refresh_masses(d);
    }
    if (scaled) keep_momentum(d, old_scale);
    refresh_external_forces(d);
  });
  d.block_partial.assign(kNodeSums * ((d.nodes.size() + kNodeBlock - 1) / kNodeBlock), 0.0);
  const std::size_t blocks = std::max(d.tris.size(), d.cracks.size()) / kEnergyBlock + 1;
  d.energy_partial.assign(blocks, 0.0);
  d.masses_dirty = false;
}

namespace {

/// Sums a block of the node loop hands back (reversal check and energy).
struct NodeSums {
  double dot = 0, kin = 0, external = 0, damping = 0, absorbing = 0, energy = 0, speed2 = 0;
};

/// Energy bookings of a node with a boundary record (rare, so out of line):
/// a prescribed component's reaction turns v_old into the prescribed v_new
/// against the element force f_el, so its work is
/// m (v_new - v_old) (v_new + v_old) / 2 - f_el h (the platens' work; the
/// dead load's is inside it), and the damping and dashpot it overrode did
/// nothing; a free component books its dead load, dashpot and damping.
[[gnu::noinline]] void boundary_node_work(const EngineData& d, long i, double vx0, double vy0,
                                          double vx, double vy, bool free_x, bool free_y, double gx,
                                          double gy, double cx, double cy, double lx, double ly,
                                          NodeSums& sum) {
  const double half_dt = 0.5 * d.dt;
  const double hx = (vx0 + vx) * half_dt, hy = (vy0 + vy) * half_dt;
  const double m = d.nodes.mass[i];
  double ex, ey;
  node_force(d, i, gx, gy, ex, ey);  // element forces + dead load
  sum.external += free_x ? gx * hx : m * (vx - vx0) * 0.5 * (vx + vx0) - (ex - gx) * hx;
  sum.external += free_y ? gy * hy : m * (vy - vy0) * 0.5 * (vy + vy0) - (ey - gy) * hy;
  sum.absorbing += (free_x ? cx * hx : 0.0) + (free_y ? cy * hy : 0.0);
  sum.damping += (free_x ? lx * hx : 0.0) + (free_y ? ly * hy : 0.0);
}

/// First node in [begin, end) with a non-finite velocity, or -1 (a sum
/// that overflowed from finite velocities).
[[gnu::cold]] long first_non_finite(const Nodes& n, long begin, long end) {
  for (long i = begin; i < end; ++i)
    if (!std::isfinite(n.vel[2 * i] + n.vel[2 * i + 1])) return i;
  return -1;
}

/// The node loop; kDamped (local or mass-proportional damping) and kLoaded
/// (some dead load) are template arguments so that a run without them has
/// no energy bookings left in its common path: only boundary-record nodes
/// book there, in their own rare branch.
template <bool kDamped, bool kLoaded>
long node_loop(EngineData& d) {
  const long nn = static_cast<long>(d.nodes.size());
  const long n_blocks = (nn + kNodeBlock - 1) / kNodeBlock;
  Nodes& n = d.nodes;
  const double dt = d.dt, half_dt = 0.5 * d.dt;
  const double local = d.damping.local, cmass = d.damping.mass_proportional;
  const bool kinetic = d.damping.kinetic;  // only kinetic damping reads the sum
  const BoundaryRecord* rec = d.bc_records.data();
  double* partial = d.block_partial.data();
  long first_bad = nn;
#pragma omp parallel for schedule(static) num_threads(thread_count(d.threads)) \
    reduction(min                                                              \
              : first_bad)
  for (long blk = 0; blk < n_blocks; ++blk) {
    NodeSums sum;
    const long end = std::min(nn, (blk + 1) * kNodeBlock);
    DeadLoadCursor loads(n.fext, blk * kNodeBlock);
    NodeListCursor records(n.bc_node, blk * kNodeBlock);
    for (long i = blk * kNodeBlock; i < end; ++i) {
      // 1/m here rather than stored: the same bits, 8 B per node less.
      if (!(n.mass[i] > 0.0)) continue;  // no active triangle: frozen
      const double inv_m = 1.0 / n.mass[i];
      double gx = 0.0, gy = 0.0;  // dead load
      if (kLoaded) loads.at(i, gx, gy);
      double fx, fy;
      node_force(d, i, gx, gy, fx, fy);
      const double vx0 = n.vel[2 * i], vy0 = n.vel[2 * i + 1];
      const long b = records.at(i);
      double cx = 0, cy = 0;  // dashpot
      if (b >= 0) {
        cx = rec[b].cxx * vx0 + rec[b].cxy * vy0;
        cy = rec[b].cxy * vx0 + rec[b].cyy * vy0;
        fx -= cx;
        fy -= cy;
      }
      double lx = 0, ly = 0;  // local + mass-proportional damping
      if (kDamped) {
        if (local > 0.0) {
          lx = local * std::fabs(fx) * sign(vx0);
          ly = local * std::fabs(fy) * sign(vy0);
          fx -= lx;
          fy -= ly;
        }
        if (cmass > 0.0) {
          const double m = n.mass[i];
          const double mx = cmass * m * vx0, my = cmass * m * vy0;
          fx -= mx;
          fy -= my;
          lx += mx;
          ly += my;
        }
      }
      double vx = vx0 + fx * inv_m * dt, vy = vy0 + fy * inv_m * dt;
      if (b >= 0) {
        bool free_x = true, free_y = true;
        if (rec[b].x != Constraint::kFree) vx = rec[b].vx, free_x = false;
        if (rec[b].y != Constraint::kFree) vy = rec[b].vy, free_y = false;
        boundary_node_work(d, i, vx0, vy0, vx, vy, free_x, free_y, gx, gy, cx, cy, lx, ly, sum);
        if (!std::isfinite(vx + vy)) first_bad = i < first_bad ? i : first_bad;
      } else {  // unweighted: the unstable mode's sign flip shows without masses
        // A non-finite vx or vy makes this product, and the block's sum,
        // non-finite (0 * inf is NaN too): the check after the block.
        sum.dot += vx0 * vx + vy0 * vy;
        sum.kin += vx0 * vx0 + vy0 * vy0;
        if (kDamped) sum.damping += (lx * (vx0 + vx) + ly * (vy0 + vy)) * half_dt;
        if (kLoaded) sum.external += (gx * (vx0 + vx) + gy * (vy0 + vy)) * half_dt;
      }
      if (kinetic) sum.energy += kinetic_energy_term(n.mass[i], vx, vy);
      sum.speed2 = std::max(sum.speed2, vx * vx + vy * vy);  // a NaN stops the run below
      n.vel[2 * i] = vx;
      n.vel[2 * i + 1] = vy;
      n.pos[2 * i] += vx * dt;
      n.pos[2 * i + 1] += vy * dt;
    }
    // Non-finite velocities of free nodes show in the block's dot product:
    // one test per block instead of one per node; the block is searched only
    // then. Positions follow from the velocities (and every node of an
    // active triangle is checked again through J).
    if (!std::isfinite(sum.dot)) {
      const long bad = first_non_finite(n, blk * kNodeBlock, end);
      if (bad >= 0 && bad < first_bad) first_bad = bad;
    }
    double* p = partial + kNodeSums * blk;
    p[0] = sum.dot;
    p[1] = sum.kin;
    p[2] = sum.external;
    p[3] = sum.damping;
    p[4] = sum.absorbing;
    p[5] = sum.energy;
    p[6] = sum.speed2;
  }
  return first_bad < nn ? first_bad : -1;
}

}  // namespace

/// Nodes are processed in fixed blocks so that the velocity-reversal sums
/// (free nodes only, sum v_old.v_new and sum |v_old|^2) and the energy sums
/// are block partials added in block order: the same figures for any thread
/// count. Energy (energy.hpp): each force's work is booked with the
/// mid-step displacement h = (v_old + v_new) dt / 2 (boundary_node_work for
/// nodes with a boundary record).
long node_update(EngineData& d) {
  const bool damped = d.damping.local > 0.0 || d.damping.mass_proportional > 0.0;
  const long bad = damped ? (d.dead_loads ? node_loop<true, true>(d) : node_loop<true, false>(d))
                          : (d.dead_loads ? node_loop<false, true>(d) : node_loop<false, false>(d));
  const long n_blocks = (static_cast<long>(d.nodes.size()) + kNodeBlock - 1) / kNodeBlock;
  const double* partial = d.block_partial.data();
  double sum[kNodeSums] = {0, 0, 0, 0, 0, 0, 0};
  for (long blk = 0; blk < n_blocks; ++blk) {
    for (int k = 0; k < kNodeSums - 1; ++k) sum[k] += partial[kNodeSums * blk + k];
    sum[kNodeSums - 1] = std::max(sum[kNodeSums - 1], partial[kNodeSums * blk + kNodeSums - 1]);
  }
  d.reversal[0] = sum[0];
  d.reversal[1] = sum[1];
  d.energy.external += sum[2];
  d.energy.nodal_damping += sum[3];
  d.energy.absorbing += sum[4];
  d.kinetic_after_step = sum[5];
  d.fastest_speed = std::sqrt(sum[kNodeSums - 1]);
  return bad;
}

}  // namespace rockfdem::fdem::detail
