// Node loop of the explicit step.
//
// Local (Cundall) damping removes alpha |f| against the velocity in each
// component: it damps without the rate dependence of viscous damping, which
// is what quasi-static stages want. Mass-proportional damping c m v is the
// classic alternative. Neither is applied to constrained components.
#include "node_update.hpp"

#include <algorithm>
#include <cmath>

#include "parallel.hpp"

namespace rockfdem::fdem::detail {
namespace {

inline double sign(double v) { return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0); }

void refresh_masses(EngineData& d) {
  const long nn = static_cast<long>(d.nodes.size());
  const long tri_slots = static_cast<long>(d.crack_slot0());
  Nodes& n = d.nodes;
  const Triangles& tr = d.tris;
#pragma omp parallel for schedule(static) num_threads(thread_count(d.threads))
  for (long i = 0; i < nn; ++i) {
    double m = 0;
    for (int k = n.slot_start[i]; k < n.slot_start[i + 1]; ++k) {
      const int s = n.slot_index[k];
      if (s >= tri_slots) break;  // slots are sorted: triangles come first
      const int t = s / 3;
      if (tr.active[t]) m += d.solids[tr.material[t]].rho * tr.area0[t] / 3.0;
    }
    n.mass[i] = m;
    n.inv_mass[i] = m > 0 ? 1.0 / m : 0.0;
    if (m == 0) n.vel[2 * i] = n.vel[2 * i + 1] = 0.0;
  }
}

void refresh_external_forces(EngineData& d) {
  Nodes& n = d.nodes;
  for (std::size_t i = 0; i < n.size(); ++i) {
    n.fext[2 * i] = n.mass[i] * d.gravity[0];
    n.fext[2 * i + 1] = n.mass[i] * d.gravity[1];
  }
  for (const NodalLoad& l : d.loads) {
    n.fext[2 * l.node] += l.fx;
    n.fext[2 * l.node + 1] += l.fy;
  }
}

/// Crack elements act only between two active triangles; an element that
/// stops acting keeps zero forces in its slots.
void refresh_crack_activity(EngineData& d) {
  Cracks& c = d.cracks;
  const std::size_t slot0 = d.crack_slot0();
  for (std::size_t e = 0; e < c.size(); ++e) {
    const bool on = d.tris.active[c.tri[2 * e]] && d.tris.active[c.tri[2 * e + 1]];
    c.active[e] = on;
    if (!on)
      for (int k = 0; k < 8; ++k) d.slots[2 * (slot0 + 4 * e) + k] = 0.0;
  }
  for (std::size_t t = 0; t < d.tris.size(); ++t)
    if (!d.tris.active[t])
      for (int k = 0; k < 6; ++k) d.slots[6 * t + k] = 0.0;
}

}  // namespace

void refresh_nodes(EngineData& d) {
  refresh_masses(d);
  refresh_external_forces(d);
  refresh_crack_activity(d);
  d.block_partial.assign(2 * ((d.nodes.size() + kNodeBlock - 1) / kNodeBlock), 0.0);
  d.masses_dirty = false;
}

/// Nodes are processed in fixed blocks so that the velocity-reversal sums
/// (free nodes only, sum v_old.v_new and sum |v_old|^2) are block partials added in block order:
/// the same figure for any thread count.
long node_update(EngineData& d) {
  const long nn = static_cast<long>(d.nodes.size());
  const long n_blocks = (nn + kNodeBlock - 1) / kNodeBlock;
  Nodes& n = d.nodes;
  const double dt = d.dt;
  const double local = d.damping.local, cmass = d.damping.mass_proportional;
  const BoundaryRecord* rec = d.bc_records.data();
  double* partial = d.block_partial.data();
  long first_bad = nn;
#pragma omp parallel for schedule(static) num_threads(thread_count(d.threads)) \
    reduction(min                                                              \
              : first_bad)
  for (long blk = 0; blk < n_blocks; ++blk) {
    double dot = 0, kin = 0;
    const long end = std::min(nn, (blk + 1) * kNodeBlock);
    for (long i = blk * kNodeBlock; i < end; ++i) {
      const double inv_m = n.inv_mass[i];
      if (inv_m == 0.0) continue;  // no active triangle: frozen
      double fx, fy;
      node_force(d, i, fx, fy);
      const double vx0 = n.vel[2 * i], vy0 = n.vel[2 * i + 1];
      const int b = n.bc[i];
      if (b >= 0) {
        fx -= rec[b].cxx * vx0 + rec[b].cxy * vy0;
        fy -= rec[b].cxy * vx0 + rec[b].cyy * vy0;
      }
      if (local > 0.0) {
        fx -= local * std::fabs(fx) * sign(vx0);
        fy -= local * std::fabs(fy) * sign(vy0);
      }
      if (cmass > 0.0) {
        const double m = n.mass[i];
        fx -= cmass * m * vx0;
        fy -= cmass * m * vy0;
      }
      double vx = vx0 + fx * inv_m * dt, vy = vy0 + fy * inv_m * dt;
      if (b >= 0) {
        if (rec[b].x != Constraint::kFree) vx = rec[b].vx;
        if (rec[b].y != Constraint::kFree) vy = rec[b].vy;
      } else {  // unweighted: the unstable mode's sign flip shows without masses
        dot += vx0 * vx + vy0 * vy;
        kin += vx0 * vx0 + vy0 * vy0;
      }
      n.vel[2 * i] = vx;
      n.vel[2 * i + 1] = vy;
      n.pos[2 * i] += vx * dt;
      n.pos[2 * i + 1] += vy * dt;
      // A non-finite velocity is caught here; positions follow from it (and
      // every node of an active triangle is checked again through J).
      if (!std::isfinite(vx + vy)) first_bad = i < first_bad ? i : first_bad;
    }
    partial[2 * blk] = dot;
    partial[2 * blk + 1] = kin;
  }
  d.reversal[0] = d.reversal[1] = 0;
  for (long blk = 0; blk < n_blocks; ++blk) {
    d.reversal[0] += partial[2 * blk];
    d.reversal[1] += partial[2 * blk + 1];
  }
  return first_bad < nn ? first_bad : -1;
}

}  // namespace rockfdem::fdem::detail
