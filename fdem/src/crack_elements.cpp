// Crack element kernel. For nodes 0,1 on one face and 3,2 facing them:
//   t = ((x1 + x2) - (x0 + x3)) / 2,  h = |t|,  e = t / h,  n = (-e_y, e_x),
//   at each end delta = x0 - x3 (x1 - x2): opening o = delta.n, slip s = delta.e.
// The law is evaluated at end 0, the midpoint and end 1 with Simpson weights
// h/6, 2h/3, h/6; the midpoint's weight goes half to each node pair. Face
// (0,1) receives -w (tau e + sigma n), face (3,2) the opposite.
#include "crack_elements.hpp"

#include <algorithm>
#include <cmath>

#include "crack_batch.hpp"
#include "parallel.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "strength_heterogeneity.hpp"

namespace rockfdem::fdem::detail {
namespace {

/// Element c's strength terms: its material's, times its factor in
/// heterogeneous models.
StrengthTerms<double> strength_terms(const EngineData& d, std::size_t c, const CrackConstants& k) {
  return d.cracks.strength.empty() ? material_terms(k)
                                   : scaled_strength_terms(k, double(d.cracks.strength[c]));
}

/// Element c's damage at its three points, widened from storage.
void point_damage(const EngineData& d, std::size_t c, double out[3]) {
  for (int i = 0; i < 3; ++i) out[i] = d.cracks.damage[3 * c + i];
}

void zero_slots(double* s) {
  for (int k = 0; k < 4; ++k) s[k] = 0.0;
}

/// The three integration points of one element with law L; the damage
/// histories are scalars so that they stay in registers.
template <class L>
inline void law_points(const CrackConstants& k, const StrengthTerms<double>& st, const double o[3],
                       const double s[3], double h, double inv_h, double& d0, double& d1,
                       double& d2, CrackPoint p[3]) {
  p[0] = L::point(k, st, o[0], s[0], h, inv_h, d0);
  p[1] = L::point(k, st, o[1], s[1], h, inv_h, d1);
  p[2] = L::point(k, st, o[2], s[2], h, inv_h, d2);
}

/// Potential of the element's three points (Simpson weights h/6, 2h/3, h/6)
/// at the damages `dmg`.
inline double element_potential(const CrackConstants& k, const double o[3], const double s[3],
                                double h, const double dmg[3]) {
  return h / 6.0 *
             (crack_point_potential(k, o[0], s[0], h, dmg[0]) +
              crack_point_potential(k, o[2], s[2], h, dmg[2])) +
         2.0 * h / 3.0 * crack_point_potential(k, o[1], s[1], h, dmg[1]);
}

/// Potential released when element c's damage grows from `before` to
/// `after` (nullptr: the element broke, everything goes): the points whose
/// damage grew release phi(D_old) - phi(D_new), a broken element its whole
/// phi(D_old). Evaluated where central differences put the change, at
/// x(n-1/2) = x(n) - v(n-1/2) dt/2, between the last force with the old
/// damage and the first with the new (energy.hpp). Out of line: only damage
/// growth gets here.
[[gnu::noinline]] double released_potential(const EngineData& d, std::size_t c,
                                            const double before[3], const double* after) {
  double os[6];
  const Placement at{d.nodes.pos.data(), d.nodes.vel.data(), 0.5 * d.energy.last_dt};
  const double h = law_openings(d, c, at, os);
  const CrackConstants k = crack_constants(d, c);
  const double weight[3] = {h / 6.0, 2.0 * h / 3.0, h / 6.0};
  double released = 0.0;
  for (int i = 0; i < 3; ++i) {
    if (after && after[i] == before[i]) continue;
    const double o = os[2 * i], s = os[2 * i + 1];
    released += weight[i] * (crack_point_potential(k, o, s, h, before[i]) -
                             (after ? crack_point_potential(k, o, s, h, after[i]) : 0.0));
  }
  return released;
}

/// Evaluates one element; returns true when it broke this step. Adds to
/// `released` the potential the law released: phi(D_old) - phi(D_new) when
/// damage grew, the whole phi(D_old) when the element broke.
[[gnu::always_inline]] inline bool crack_element(const EngineData& d, std::size_t c, float* damage,
                                                 double* out, double& sum_a2, double& sum_b2,
                                                 double& released) {
  const int* nd = &d.cracks.nodes[4 * c];
  const double* p = d.nodes.pos.data();
  const double x0 = p[2 * nd[0]], y0 = p[2 * nd[0] + 1], x1 = p[2 * nd[1]], y1 = p[2 * nd[1] + 1];
  const double x2 = p[2 * nd[2]], y2 = p[2 * nd[2] + 1], x3 = p[2 * nd[3]], y3 = p[2 * nd[3] + 1];
  const double tx = 0.5 * ((x1 + x2) - (x0 + x3)), ty = 0.5 * ((y1 + y2) - (y0 + y3));
  const double h = std::sqrt(tx * tx + ty * ty);
  const double inv_h = 1.0 / h;
  const double ex = tx * inv_h, ey = ty * inv_h;
  const double nx = -ey, ny = ex;
  const double d0x = x0 - x3, d0y = y0 - y3, d1x = x1 - x2, d1y = y1 - y2;
  double o0 = d0x * nx + d0y * ny, s0 = d0x * ex + d0y * ey;
  double o1 = d1x * nx + d1y * ny, s1 = d1x * ex + d1y * ey;
  // The material's constants and strength terms, the latter scaled by the
  // element's factor in heterogeneous models.
  const CrackConstants& k = d.crack_laws[d.cracks.material[c]];
  const StrengthTerms<double> st = strength_terms(d, c, k);
  double o[3] = {o0, 0.5 * (o0 + o1), o1}, s[3] = {s0, 0.5 * (s0 + s1), s1};
  if (!d.cracks.offset.empty()) {  // re-joined or pre-stressed elements (per point)
    const float* off = &d.cracks.offset[6 * c];
    for (int i = 0; i < 3; ++i) {
      o[i] -= off[2 * i];
      s[i] -= off[2 * i + 1];
    }
  }
  // The law raises a local copy; the history is written back only when it
  // grew (rare), which is also when the energy ledger books the release.
  const double before[3] = {damage[0], damage[1], damage[2]};
  double d0 = before[0], d1 = before[1], d2 = before[2];
  CrackPoint pt[3];
  with_crack_law(k.law, [&](auto law) {  // one dispatch per element
    law_points<decltype(law)>(k, st, o, s, h, inv_h, d0, d1, d2, pt);
  });
  d0 = round_up_to_float(d0);  // the history as it will be stored
  d1 = round_up_to_float(d1);
  d2 = round_up_to_float(d2);
  const CrackPoint &p0 = pt[0], &pm = pt[1], &p1 = pt[2];
  // Damage never decreases, so each difference is >= 0 and their sum is
  // > 0 exactly when some point's damage grew. Only then can the element
  // break (it is skipped once two points reach 1).
  if ((d0 - before[0]) + (d1 - before[1]) + (d2 - before[2]) > 0.0) {
    const double dn[3] = {d0, d1, d2};
    const bool broke = k.breaks && (d0 >= 1.0) + (d1 >= 1.0) + (d2 >= 1.0) >= 2;
    released += released_potential(d, c, before, broke ? nullptr : dn);
    damage[0] = static_cast<float>(d0);  // exact: rounded above
    damage[1] = static_cast<float>(d1);
    damage[2] = static_cast<float>(d2);
    if (broke) {
      sum_a2 = p0.a * p0.a + pm.a * pm.a + p1.a * p1.a;
      sum_b2 = p0.b * p0.b + pm.b * pm.b + p1.b * p1.b;
      return true;
    }
  }
  const double w_end = h / 6.0, w_mid = h / 3.0;
  const double sn0 = w_end * p0.sigma + w_mid * pm.sigma, st0 = w_end * p0.tau + w_mid * pm.tau;
  const double sn1 = w_end * p1.sigma + w_mid * pm.sigma, st1 = w_end * p1.tau + w_mid * pm.tau;
  const double f0x = -(st0 * ex + sn0 * nx), f0y = -(st0 * ey + sn0 * ny);
  const double f1x = -(st1 * ex + sn1 * nx), f1y = -(st1 * ey + sn1 * ny);
  out[0] = f0x;  // nodes 3, 2 take -f0, -f1 (the gather negates)
  out[1] = f0y;
  out[2] = f1x;
  out[3] = f1y;
  return false;
}

}  // namespace

double crack_end_openings(const EngineData& d, std::size_t c, const Placement& at, double out[4]) {
  const int* nd = &d.cracks.nodes[4 * c];
  double x[4], y[4];
  for (int k = 0; k < 4; ++k) {
    x[k] = at.x(nd[k]);
    y[k] = at.y(nd[k]);
  }
  const double tx = 0.5 * (x[1] + x[2] - x[0] - x[3]), ty = 0.5 * (y[1] + y[2] - y[0] - y[3]);
  const double h = std::sqrt(tx * tx + ty * ty), ex = tx / h, ey = ty / h;
  for (int end = 0; end < 2; ++end) {
    const double dx = x[end] - x[3 - end], dy = y[end] - y[3 - end];
    out[2 * end] = -dx * ey + dy * ex;
    out[2 * end + 1] = dx * ex + dy * ey;
  }
  return h;
}

double crack_end_openings(const EngineData& d, std::size_t c, double out[4]) {
  return crack_end_openings(d, c, Placement{d.nodes.pos.data(), d.nodes.vel.data(), 0.0}, out);
}

double crack_point_openings(const EngineData& d, std::size_t c, const Placement& at,
                            double out[6]) {
  double ends[4];
  const double h = crack_end_openings(d, c, at, ends);
  out[0] = ends[0];
  out[1] = ends[1];
  out[2] = 0.5 * (ends[0] + ends[2]);
  out[3] = 0.5 * (ends[1] + ends[3]);
  out[4] = ends[2];
  out[5] = ends[3];
  return h;
}

double crack_point_openings(const EngineData& d, std::size_t c, double out[6]) {
  return crack_point_openings(d, c, Placement{d.nodes.pos.data(), d.nodes.vel.data(), 0.0}, out);
}

void subtract_offsets(const EngineData& d, std::size_t c, double os[6]) {
  if (d.cracks.offset.empty()) return;
  for (int i = 0; i < 6; ++i) os[i] -= d.cracks.offset[6 * c + i];
}

double law_openings(const EngineData& d, std::size_t c, const Placement& at, double os[6]) {
  const double h = crack_point_openings(d, c, at, os);
  subtract_offsets(d, c, os);
  return h;
}

double law_openings(const EngineData& d, std::size_t c, double os[6]) {
  return law_openings(d, c, Placement{d.nodes.pos.data(), d.nodes.vel.data(), 0.0}, os);
}

double crack_element_energy(const EngineData& d, std::size_t c, const Placement& at) {
  if (!d.cracks.active[c] || d.cracks.state[c] == std::uint8_t(CrackState::kBroken)) return 0.0;
  double os[6];
  const double h = law_openings(d, c, at, os);
  const double o[3] = {os[0], os[2], os[4]}, s[3] = {os[1], os[3], os[5]};
  double damage[3];
  point_damage(d, c, damage);
  return element_potential(crack_constants(d, c), o, s, h, damage);
}

double crack_element_energy(const EngineData& d, std::size_t c) {
  return crack_element_energy(d, c, Placement{d.nodes.pos.data(), d.nodes.vel.data(), 0.0});
}

void crack_point_stresses(const EngineData& d, std::size_t c, double out[6]) {
  for (int i = 0; i < 6; ++i) out[i] = 0.0;
  if (!d.cracks.active[c] || d.cracks.state[c] == std::uint8_t(CrackState::kBroken)) return;
  double os[6];
  const double h = law_openings(d, c, os);
  const CrackConstants& k = d.crack_laws[d.cracks.material[c]];
  const StrengthTerms<double> st = strength_terms(d, c, k);
  double damage[3];
  point_damage(d, c, damage);
  with_crack_law(k.law, [&](auto law) {
    for (int i = 0; i < 3; ++i) {
      const CrackPoint p =
          decltype(law)::point(k, st, os[2 * i], os[2 * i + 1], h, 1.0 / h, damage[i]);
      out[2 * i] = p.sigma;
      out[2 * i + 1] = p.tau;
    }
  });
}

FailureMode classify_failure(double sum_a2, double sum_b2) {
  const double total = sum_a2 + sum_b2;
  if (!(total > 0.0)) return FailureMode::kMixed;
  const double r = sum_a2 / total;
  if (r >= 0.9) return FailureMode::kModeI;
  if (r <= 0.1) return FailureMode::kModeII;
  return FailureMode::kMixed;
}

namespace {

/// Whether element c takes the batch path: active, not broken, material
/// `material` (one of a batched law, one per batch), and not an intact element with
/// a damage history (the scalar loop would mark it yielding; growth marks
/// it in the same step, so this is only a guard).
inline bool batchable(const EngineData& d, long c, int material) {
  const std::uint8_t state = d.cracks.state[c];
  if (!d.cracks.active[c] || state == std::uint8_t(CrackState::kBroken) ||
      d.cracks.material[c] != material)
    return false;
  const float* dmg = &d.cracks.damage[3 * c];
  return state != std::uint8_t(CrackState::kIntact) ||
         (dmg[0] == 0.0 && dmg[1] == 0.0 && dmg[2] == 0.0);
}

/// Runs the batch; its lanes whose damage does not grow get their slots,
/// the others are left to the scalar path.
void flush_cracks(CrackBatch& b, int n, const int* element, const CrackConstants& k, bool scaled,
                  double* slots, std::uint8_t* scalar, long begin) {
  run_crack_batch(b, n, k, scaled);
  for (int r = 0; r < n; ++r) {
    const long c = element[r];
    if (b.grows[r] != 0.0) {
      scalar[c - begin] = 1;
      continue;
    }
    double* out = slots + 4 * c;  // nodes 0, 1 (b.out[4..7] are their negatives)
    for (int i = 0; i < 4; ++i) out[i] = b.out[i][r];
  }
}

/// How many elements ahead the batch's gather asks for node positions: a
/// crack element's far face belongs to a triangle that the locality order
/// may have put far away, and its positions are then a cache miss (measured
/// at 420k triangles: half the crack loop's samples waited on that load).
constexpr long kGatherAhead = 8;

inline void prefetch_nodes(const double* pos, const int* nodes) {
  for (int j = 0; j < 4; ++j) __builtin_prefetch(pos + 2 * nodes[j]);
}

/// The batch pass over elements [begin, end): marks in `scalar` the ones the
/// scalar loop must evaluate (all others have their slots).
void batch_pass(const EngineData& d, long begin, long end, CrackBatch& b, int* element,
                double* slots, std::uint8_t* scalar) {
  for (long c = begin; c < end; ++c) scalar[c - begin] = 1;
  int material = -1;
  for (long c = begin; c < end && material < 0; ++c)
    if (d.cracks.active[c] && d.cracks.state[c] != std::uint8_t(CrackState::kBroken) &&
        crack_law_batched(d.crack_laws[d.cracks.material[c]].law))
      material = d.cracks.material[c];
  if (material < 0) return;
  const CrackConstants& k = d.crack_laws[material];
  const double* p = d.nodes.pos.data();
  const bool offsets = !d.cracks.offset.empty();
  const bool scaled = !d.cracks.strength.empty();
  const long nc = static_cast<long>(d.cracks.size());
  int n = 0;
  for (long c = begin; c < end; ++c) {
    if (c + kGatherAhead < nc) prefetch_nodes(p, &d.cracks.nodes[4 * (c + kGatherAhead)]);
    if (!batchable(d, c, material)) continue;
    scalar[c - begin] = 0;
    const int* nd = &d.cracks.nodes[4 * c];
    for (int j = 0; j < 4; ++j) {
      b.x[j][n] = p[2 * nd[j]];
      b.y[j][n] = p[2 * nd[j] + 1];
    }
    for (int i = 0; i < 3; ++i) {
      b.off_o[i][n] = offsets ? d.cracks.offset[6 * c + 2 * i] : 0.0;
      b.off_s[i][n] = offsets ? d.cracks.offset[6 * c + 2 * i + 1] : 0.0;
      b.damage[i][n] = d.cracks.damage[3 * c + i];
    }
    if (scaled) b.strength[n] = d.cracks.strength[c];
    element[n++] = static_cast<int>(c);
    if (n == kCrackBatch) {
      flush_cracks(b, n, element, k, scaled, slots, scalar, begin);
      n = 0;
    }
  }
  if (n > 0) flush_cracks(b, n, element, k, scaled, slots, scalar, begin);
}

}  // namespace

/// Fixed blocks of kEnergyBlock elements: the released potential is a
/// deterministic block sum (energy.hpp). In each block the elements of the
/// first material with a batched law (rock) go through the batch kernel first (crack_batch.hpp);
/// the rest, and those whose damage grows, through crack_element in element order.
long crack_forces(EngineData& d) {
  const long nc = static_cast<long>(d.cracks.size());
  const long n_blocks = (nc + kEnergyBlock - 1) / kEnergyBlock;
  double* slots = d.slots.data() + 2 * d.crack_slot0();
  float* damage = d.cracks.damage.data();
  std::uint8_t* state = d.cracks.state.data();
  const std::uint8_t* active = d.cracks.active.data();
  double* partial = d.energy_partial.data();
  const auto step = static_cast<std::int32_t>(d.step);
  long broke[3] = {0, 0, 0};  // by broken_mode_entry; integers: any order, the same sums
#pragma omp parallel num_threads(thread_count(d.threads)) reduction(+ : broke[:3])
  {
    CrackBatch batch{};  // per thread (zeroed: padding lanes are read)
    int element[kCrackBatch];
    std::uint8_t scalar[kEnergyBlock];
#pragma omp for schedule(static)
    for (long b = 0; b < n_blocks; ++b) {
      double released = 0;
      std::uint8_t any_broke = 0;
      const long begin = b * kEnergyBlock, end = std::min(nc, (b + 1) * kEnergyBlock);
      if (d.crack_batch) {
        batch_pass(d, begin, end, batch, element, slots, scalar);
      } else {
        for (long c = begin; c < end; ++c) scalar[c - begin] = 1;
      }
      for (long c = begin; c < end; ++c) {
        if (!scalar[c - begin]) continue;
        if (!active[c] || state[c] == std::uint8_t(CrackState::kBroken)) continue;
        double sum_a2 = 0, sum_b2 = 0;
        double* out = slots + 4 * c;
        float* dmg = damage + 3 * c;
        if (crack_element(d, c, dmg, out, sum_a2, sum_b2, released)) {
          zero_slots(out);
          state[c] = std::uint8_t(CrackState::kBroken);
          const auto mode = std::uint8_t(classify_failure(sum_a2, sum_b2));
          d.cracks.mode[c] = mode;
          d.cracks.broken_step[c] = step;
          any_broke = 1;
          ++broke[broken_mode_entry(mode)];
        } else if (state[c] == std::uint8_t(CrackState::kIntact) &&
                   (dmg[0] > 0.0 || dmg[1] > 0.0 || dmg[2] > 0.0)) {
          state[c] = std::uint8_t(CrackState::kYielding);
        }
      }
      partial[b] = released;
      d.cracks.broke_in_block[b] = any_broke;
    }
  }
  double released = 0;
  for (long b = 0; b < n_blocks; ++b) released += partial[b];
  d.energy.fracture += released;
  for (int k = 0; k < 3; ++k) d.broken_by_mode[k] += broke[k];
  return broke[0] + broke[1] + broke[2];
}

}  // namespace rockfdem::fdem::detail
