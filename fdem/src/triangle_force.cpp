// Triangle forces: F = Fc F0^-1, J = det F, B = F F^T,
//   sigma = alpha [ (mu/J)(B - I) + (lambda/2)(J - 1/J) I + F S0 F^T / J + eta D ],
// then f_i = sigma n_i / 2 with n_i the outward normal (length = edge
// length) of the edge opposite node i in the current configuration.
//
// The initial stress S0 is pushed forward with the deformation (F S0 F^T / J)
// so that a rigidly rotated pre-stressed element carries its stress along
// (objectivity); for small strains it is S0 itself. alpha scales the whole
// stress, initial part included: that is what core softening needs when the
// in-situ state is held as S0 (reference sec. 5).
#include "triangle_force.hpp"

#include <cmath>

#include "parallel.hpp"

namespace rockfdem::fdem::detail {
namespace {

/// Everything the stress needs, read once per triangle.
struct TriangleState {
  double x[3], y[3];  // current positions
  double F[4];        // deformation gradient, row-major
  double J;
};

inline void load_state(const EngineData& d, std::size_t t, TriangleState& s) {
  const int* nd = &d.tris.nodes[3 * t];
  const double* p = d.nodes.pos.data();
  for (int k = 0; k < 3; ++k) {
    s.x[k] = p[2 * nd[k]];
    s.y[k] = p[2 * nd[k] + 1];
  }
  const double* g = &d.tris.ref_inv[4 * t];
  const double e1x = s.x[1] - s.x[0], e1y = s.y[1] - s.y[0];
  const double e2x = s.x[2] - s.x[0], e2y = s.y[2] - s.y[0];
  s.F[0] = e1x * g[0] + e2x * g[2];
  s.F[1] = e1x * g[1] + e2x * g[3];
  s.F[2] = e1y * g[0] + e2y * g[2];
  s.F[3] = e1y * g[1] + e2y * g[3];
  s.J = s.F[0] * s.F[3] - s.F[1] * s.F[2];
}

/// Cauchy stress of a sound triangle (J > 0) into sig[3].
inline void stress(const EngineData& d, std::size_t t, const TriangleState& s, double sig[3]) {
  const SolidConstants& m = d.solids[d.tris.material[t]];
  const double* F = s.F;
  const double inv_j = 1.0 / s.J;
  const double vol = 0.5 * m.lambda * (s.J - inv_j);
  const double mu_j = m.mu * inv_j;
  sig[0] = mu_j * (F[0] * F[0] + F[1] * F[1] - 1.0) + vol;
  sig[1] = mu_j * (F[2] * F[2] + F[3] * F[3] - 1.0) + vol;
  sig[2] = mu_j * (F[0] * F[2] + F[1] * F[3]);
  if (!d.tris.sigma0.empty()) {
    const double* s0 = &d.tris.sigma0[3 * t];
    // P = F S0, then P F^T / J.
    const double p00 = F[0] * s0[0] + F[1] * s0[2], p01 = F[0] * s0[2] + F[1] * s0[1];
    const double p10 = F[2] * s0[0] + F[3] * s0[2], p11 = F[2] * s0[2] + F[3] * s0[1];
    sig[0] += (p00 * F[0] + p01 * F[1]) * inv_j;
    sig[1] += (p10 * F[2] + p11 * F[3]) * inv_j;
    sig[2] += (p00 * F[2] + p01 * F[3]) * inv_j;
  }
  const double eta = d.tris.eta[t];
  if (eta > 0.0) {
    // L = [v1 - v0, v2 - v0] Fc^-1, D = sym(L).
    const int* nd = &d.tris.nodes[3 * t];
    const double* v = d.nodes.vel.data();
    const double d1x = v[2 * nd[1]] - v[2 * nd[0]], d1y = v[2 * nd[1] + 1] - v[2 * nd[0] + 1];
    const double d2x = v[2 * nd[2]] - v[2 * nd[0]], d2y = v[2 * nd[2] + 1] - v[2 * nd[0] + 1];
    const double e1x = s.x[1] - s.x[0], e1y = s.y[1] - s.y[0];
    const double e2x = s.x[2] - s.x[0], e2y = s.y[2] - s.y[0];
    const double inv_det = 1.0 / (e1x * e2y - e2x * e1y);
    const double l00 = (d1x * e2y - d2x * e1y) * inv_det;
    const double l01 = (d2x * e1x - d1x * e2x) * inv_det;
    const double l10 = (d1y * e2y - d2y * e1y) * inv_det;
    const double l11 = (d2y * e1x - d1y * e2x) * inv_det;
    sig[0] += eta * l00;
    sig[1] += eta * l11;
    sig[2] += eta * 0.5 * (l01 + l10);
  }
  const double alpha = d.tris.alpha[t];
  sig[0] *= alpha;
  sig[1] *= alpha;
  sig[2] *= alpha;
}

/// f_i = sigma n / 2 for the edge j->k opposite node i, n = (yk - yj, xj - xk).
inline void nodal_forces(const TriangleState& s, const double sig[3], double* out) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const double nx = s.y[k] - s.y[j], ny = s.x[j] - s.x[k];
    out[2 * i] = 0.5 * (sig[0] * nx + sig[2] * ny);
    out[2 * i + 1] = 0.5 * (sig[2] * nx + sig[1] * ny);
  }
}

}  // namespace

long triangle_forces(EngineData& d) {
  const long nt = static_cast<long>(d.tris.size());
  double* slots = d.slots.data();
  const std::uint8_t* active = d.tris.active.data();
  long first_bad = nt;
#pragma omp parallel for schedule(static) num_threads(thread_count(d.threads)) \
    reduction(min                                                              \
              : first_bad)
  for (long t = 0; t < nt; ++t) {
    if (!active[t]) continue;  // an inactive triangle's slots are kept at zero
    TriangleState s;
    load_state(d, t, s);
    if (!(s.J > 0.0)) {
      first_bad = t < first_bad ? t : first_bad;
      continue;
    }
    double sig[3];
    stress(d, t, s, sig);
    nodal_forces(s, sig, slots + 6 * t);
  }
  return first_bad < nt ? first_bad : -1;
}

std::array<double, 3> triangle_stress(const EngineData& d, std::size_t t, double& J) {
  TriangleState s;
  load_state(d, t, s);
  J = s.J;
  std::array<double, 3> sig{0.0, 0.0, 0.0};
  if (s.J > 0.0 && d.tris.active[t]) stress(d, t, s, sig.data());
  return sig;
}

double triangle_strain_energy(const EngineData& d, std::size_t t) {
  if (!d.tris.active[t]) return 0.0;
  TriangleState s;
  load_state(d, t, s);
  if (!(s.J > 0.0)) return 0.0;
  const SolidConstants& m = d.solids[d.tris.material[t]];
  const double* F = s.F;
  const double tr_b = F[0] * F[0] + F[1] * F[1] + F[2] * F[2] + F[3] * F[3];
  const double ln_j = std::log(s.J);
  const double w =
      0.5 * m.mu * (tr_b - 2.0) - m.mu * ln_j + 0.25 * m.lambda * (s.J * s.J - 1.0 - 2.0 * ln_j);
  return d.tris.alpha[t] * d.tris.area0[t] * w;
}

}  // namespace rockfdem::fdem::detail
