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

#include <algorithm>
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

/// Deformation from positions already in s.x, s.y.
inline void deformation(const EngineData& d, std::size_t t, TriangleState& s) {
  const double* g = &d.tris.ref_inv[4 * t];
  const double e1x = s.x[1] - s.x[0], e1y = s.y[1] - s.y[0];
  const double e2x = s.x[2] - s.x[0], e2y = s.y[2] - s.y[0];
  s.F[0] = e1x * g[0] + e2x * g[2];
  s.F[1] = e1x * g[1] + e2x * g[3];
  s.F[2] = e1y * g[0] + e2y * g[2];
  s.F[3] = e1y * g[1] + e2y * g[3];
  s.J = s.F[0] * s.F[3] - s.F[1] * s.F[2];
}

inline void load_state(const EngineData& d, std::size_t t, TriangleState& s) {
  const int* nd = &d.tris.nodes[3 * t];
  const double* p = d.nodes.pos.data();
  for (int k = 0; k < 3; ++k) {
    s.x[k] = p[2 * nd[k]];
    s.y[k] = p[2 * nd[k] + 1];
  }
  deformation(d, t, s);
}

inline void load_state(const EngineData& d, std::size_t t, const Placement& at, TriangleState& s) {
  const int* nd = &d.tris.nodes[3 * t];
  for (int k = 0; k < 3; ++k) {
    s.x[k] = at.x(nd[k]);
    s.y[k] = at.y(nd[k]);
  }
  deformation(d, t, s);
}

/// Velocity gradient L = [v1 - v0, v2 - v0] Fc^-1 (row-major) and
/// det Fc = 2 A (the current area's double).
struct VelocityGradient {
  double l00, l01, l10, l11, det;
};

inline VelocityGradient velocity_gradient(const EngineData& d, std::size_t t,
                                          const TriangleState& s) {
  const int* nd = &d.tris.nodes[3 * t];
  const double* v = d.nodes.vel.data();
  const double d1x = v[2 * nd[1]] - v[2 * nd[0]], d1y = v[2 * nd[1] + 1] - v[2 * nd[0] + 1];
  const double d2x = v[2 * nd[2]] - v[2 * nd[0]], d2y = v[2 * nd[2] + 1] - v[2 * nd[0] + 1];
  const double e1x = s.x[1] - s.x[0], e1y = s.y[1] - s.y[0];
  const double e2x = s.x[2] - s.x[0], e2y = s.y[2] - s.y[0];
  const double det = e1x * e2y - e2x * e1y;
  const double inv_det = 1.0 / det;
  return {(d1x * e2y - d2x * e1y) * inv_det, (d2x * e1x - d1x * e2x) * inv_det,
          (d1y * e2y - d2y * e1y) * inv_det, (d2y * e1x - d1y * e2x) * inv_det, det};
}

/// What the force loop needs to book the viscous stress's work (energy.hpp).
struct ViscousWork {
  float* last;        ///< w of the last step, 3 per triangle (Triangles::viscous_stress)
  double quarter_dt;  ///< dt / 4: dt/2 times the area's 1/2 of the Jacobian determinant
};

/// Cauchy stress of a sound triangle (J > 0) into sig[3]. With `work`, a
/// viscous triangle returns the work of its viscous stress booked this step
/// and keeps w(n) = dt/2 A sigma_v(n) for the next:
///   (w(n) + w(n-1)) : D(n),
/// its force's work with v(n-1/2), and the last force's with the same
/// velocities (the second half of that step's mid-step velocity); 0 for the
/// others.
inline double stress(const EngineData& d, std::size_t t, const TriangleState& s, double sig[3],
                     const ViscousWork* work = nullptr) {
  const SolidConstants& m = d.solids[d.tris.material[t]];
  const double* F = s.F;
  const double inv_j = 1.0 / s.J;
  const double vol = 0.5 * m.lambda * (s.J - inv_j);
  const double mu_j = m.mu * inv_j;
  sig[0] = mu_j * (F[0] * F[0] + F[1] * F[1] - 1.0) + vol;
  sig[1] = mu_j * (F[2] * F[2] + F[3] * F[3] - 1.0) + vol;
  sig[2] = mu_j * (F[0] * F[2] + F[1] * F[3]);
  if (!d.tris.sigma0.empty()) {
    const double s0[3] = {d.tris.sigma0[3 * t], d.tris.sigma0[3 * t + 1], d.tris.sigma0[3 * t + 2]};
    // P = F S0, then P F^T / J.
    const double p00 = F[0] * s0[0] + F[1] * s0[2], p01 = F[0] * s0[2] + F[1] * s0[1];
    const double p10 = F[2] * s0[0] + F[3] * s0[2], p11 = F[2] * s0[2] + F[3] * s0[1];
    sig[0] += (p00 * F[0] + p01 * F[1]) * inv_j;
    sig[1] += (p10 * F[2] + p11 * F[3]) * inv_j;
    sig[2] += (p00 * F[2] + p01 * F[3]) * inv_j;
  }
  double booked = 0.0;
  const double eta = d.tris.eta[t];
  if (eta > 0.0) {  // D = sym(L)
    const VelocityGradient g = velocity_gradient(d, t, s);
    const double l00 = g.l00, l01 = g.l01, l10 = g.l10, l11 = g.l11;
    sig[0] += eta * l00;
    sig[1] += eta * l11;
    sig[2] += eta * 0.5 * (l01 + l10);
    if (work) {
      const double dxy = 0.5 * (l01 + l10);
      const double k = work->quarter_dt * g.det * (d.tris.alpha[t] * eta);
      const double w0 = k * l00, w1 = k * l11, w2 = k * dxy;
      float* last = work->last + 3 * t;
      booked = (w0 + last[0]) * l00 + (w1 + last[1]) * l11 + 2.0 * (w2 + last[2]) * dxy;
      last[0] = static_cast<float>(w0);
      last[1] = static_cast<float>(w1);
      last[2] = static_cast<float>(w2);
    }
  }
  const double alpha = d.tris.alpha[t];
  sig[0] *= alpha;
  sig[1] *= alpha;
  sig[2] *= alpha;
  return booked;
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

namespace {

/// The force loop over fixed blocks of kEnergyBlock triangles, so that the
/// viscous work (stress() above) is a deterministic block sum; kViscous:
/// some triangle has viscous damping (only then is the work booked).
template <bool kViscous>
long triangle_loop(EngineData& d) {
  const long nt = static_cast<long>(d.tris.size());
  const long n_blocks = (nt + kEnergyBlock - 1) / kEnergyBlock;
  double* slots = d.slots.data();
  const std::uint8_t* active = d.tris.active.data();
  const ViscousWork work{d.tris.viscous_stress.data(), 0.25 * d.dt};
  double* partial = d.energy_partial.data();
  long first_bad = nt;
#pragma omp parallel for schedule(static) num_threads(thread_count(d.threads)) \
    reduction(min                                                              \
              : first_bad)
  for (long b = 0; b < n_blocks; ++b) {
    double viscous = 0;
    const long end = std::min(nt, (b + 1) * kEnergyBlock);
    for (long t = b * kEnergyBlock; t < end; ++t) {
      if (!active[t]) continue;  // an inactive triangle's slots are kept at zero
      TriangleState s;
      load_state(d, t, s);
      if (!(s.J > 0.0)) {
        first_bad = t < first_bad ? t : first_bad;
        continue;
      }
      double sig[3];
      if (kViscous)
        viscous += stress(d, t, s, sig, &work);
      else
        stress(d, t, s, sig);
      nodal_forces(s, sig, slots + 6 * t);
    }
    if (kViscous) partial[b] = viscous;
  }
  if (kViscous) {
    double viscous = 0;
    for (long b = 0; b < n_blocks; ++b) viscous += partial[b];
    d.energy.viscous += viscous;
  }
  return first_bad < nt ? first_bad : -1;
}

}  // namespace

long triangle_forces(EngineData& d) {
  return d.tris.viscous_stress.empty() ? triangle_loop<false>(d) : triangle_loop<true>(d);
}

std::array<double, 3> triangle_stress(const EngineData& d, std::size_t t, double& J) {
  TriangleState s;
  load_state(d, t, s);
  J = s.J;
  std::array<double, 3> sig{0.0, 0.0, 0.0};
  if (s.J > 0.0 && d.tris.active[t]) stress(d, t, s, sig.data());
  return sig;
}

double triangle_stress_zz(const EngineData& d, std::size_t t, double sigma0_zz) {
  const SolidConstants& m = d.solids[d.tris.material[t]];
  TriangleState s;
  load_state(d, t, s);
  if (!m.plane_strain || !(s.J > 0.0) || !d.tris.active[t]) return 0.0;
  // B_zz = 1: only the volumetric term and the initial stress act along z.
  const float* s0 = d.tris.sigma0.empty() ? nullptr : &d.tris.sigma0[3 * t];
  const bool reset = !s0 || (s0[0] == 0.0 && s0[1] == 0.0 && s0[2] == 0.0);
  const double initial = reset ? 0.0 : sigma0_zz / s.J;
  return d.tris.alpha[t] * (0.5 * m.lambda * (s.J - 1.0 / s.J) + initial);
}

namespace {

/// W(F) of Munjiza's law per reference area.
inline double hyperelastic_density(const SolidConstants& m, const TriangleState& s) {
  const double* F = s.F;
  const double tr_b = F[0] * F[0] + F[1] * F[1] + F[2] * F[2] + F[3] * F[3];
  const double ln_j = std::log(s.J);
  return 0.5 * m.mu * (tr_b - 2.0) - m.mu * ln_j + 0.25 * m.lambda * (s.J * s.J - 1.0 - 2.0 * ln_j);
}

}  // namespace

double triangle_strain_energy(const EngineData& d, std::size_t t) {
  if (!d.tris.active[t]) return 0.0;
  TriangleState s;
  load_state(d, t, s);
  if (!(s.J > 0.0)) return 0.0;
  return d.tris.alpha[t] * d.tris.area0[t] * hyperelastic_density(d.solids[d.tris.material[t]], s);
}

double triangle_stored_energy(const EngineData& d, std::size_t t, const Placement& at) {
  if (!d.tris.active[t]) return 0.0;
  TriangleState s;
  load_state(d, t, at, s);
  if (!(s.J > 0.0)) return 0.0;
  double w = hyperelastic_density(d.solids[d.tris.material[t]], s);
  if (!d.tris.sigma0.empty()) {  // S0 : E with E = (F^T F - I) / 2
    const float* s0 = &d.tris.sigma0[3 * t];
    const double* F = s.F;
    const double exx = 0.5 * (F[0] * F[0] + F[2] * F[2] - 1.0);
    const double eyy = 0.5 * (F[1] * F[1] + F[3] * F[3] - 1.0);
    const double exy = 0.5 * (F[0] * F[1] + F[2] * F[3]);
    w += s0[0] * exx + s0[1] * eyy + 2.0 * s0[2] * exy;
  }
  return d.tris.alpha[t] * d.tris.area0[t] * w;
}

double triangle_viscous_pending(const EngineData& d, std::size_t t) {
  if (d.tris.viscous_stress.empty() || !d.tris.active[t]) return 0.0;
  const float* last = &d.tris.viscous_stress[3 * t];
  if (last[0] == 0.0 && last[1] == 0.0 && last[2] == 0.0) return 0.0;
  TriangleState s;
  load_state(d, t, s);
  if (!(s.J > 0.0)) return 0.0;
  const VelocityGradient g = velocity_gradient(d, t, s);
  return last[0] * g.l00 + last[1] * g.l11 + last[2] * (g.l01 + g.l10);
}

}  // namespace rockfdem::fdem::detail
