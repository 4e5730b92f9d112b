// Stability limit. For a constant-strain triangle with lumped mass
// M = rho A0 / 3 I and stiffness K = A0 B^T D B, M^-1 K = (3 / rho) B^T D B,
// whose largest eigenvalue equals that of the 3x3 matrix D^1/2 (B B^T) D^1/2:
// a closed form per triangle, no 6x6 eigenproblem. The viscous stress eta D
// gives C = eta A0 B^T V B with V = diag(1, 1, 1/2) (engineering shear), and
// the damping ratio of the stiffest mode is bounded by
// lambda_max(M^-1 C) / (2 omega).
#include "stable_dt.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "contact.hpp"
#include "crack_elements.hpp"
#include "node_update.hpp"
#include "parallel.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "triangle_geometry.hpp"

namespace rockfdem::fdem::detail {

double damped_limit(const EngineData& d, double omega, double xi_viscous);

namespace {

/// B B^T for the CST with shape-function gradients from F0^-1.
Eigen::Matrix3d gradient_product(const double* g) {
  const double b1 = g[0], c1 = g[1], b2 = g[2], c2 = g[3];
  const double b0 = -(b1 + b2), c0 = -(c1 + c2);
  const double sbb = b0 * b0 + b1 * b1 + b2 * b2;
  const double scc = c0 * c0 + c1 * c1 + c2 * c2;
  const double sbc = b0 * c0 + b1 * c1 + b2 * c2;
  Eigen::Matrix3d m;
  m << sbb, 0, sbc, 0, scc, sbc, sbc, sbc, sbb + scc;
  return m;
}

double largest_eigenvalue(const Eigen::Matrix3d& sym) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(sym, Eigen::EigenvaluesOnly);
  return solver.eigenvalues()(2);
}

/// Square root of the Voigt elasticity matrix [[a, l, 0], [l, a, 0], [0, 0, mu]].
Eigen::Matrix3d elasticity_sqrt(double lambda, double mu) {
  const double a = lambda + 2.0 * mu;
  const double s1 = std::sqrt(a + lambda), s2 = std::sqrt(a - lambda);
  Eigen::Matrix3d r = Eigen::Matrix3d::Zero();
  r(0, 0) = r(1, 1) = 0.5 * (s1 + s2);
  r(0, 1) = r(1, 0) = 0.5 * (s1 - s2);
  r(2, 2) = std::sqrt(mu);
  return r;
}

/// Gershgorin row sums of the crack elements' penalty stiffness, mass
/// normalised: node 0 couples to itself and its facing node 3 with weight
/// 1/3 and to the other pair with 1/6 (Simpson's consistent weights).
void add_crack_rows(const EngineData& d, std::vector<double>& row) {
  const float* m = d.nodes.mass.data();
  for (std::size_t c = 0; c < d.cracks.size(); ++c) {
    if (!d.cracks.active[c] || d.cracks.state[c] == std::uint8_t(CrackState::kBroken)) continue;
    const CrackConstants& k = d.crack_laws[d.cracks.material[c]];
    const double pen = std::max(k.pn, k.pt);
    const int* nd = &d.cracks.nodes[4 * c];
    // For node j: facing node, and the two nodes of the other end.
    static constexpr int facing[4] = {3, 2, 1, 0}, other[4] = {1, 0, 3, 2};
    for (int j = 0; j < 4; ++j) {
      const double mi = m[nd[j]];
      if (mi <= 0) continue;
      const double mf = m[nd[facing[j]]], mo = m[nd[other[j]]], mof = m[nd[facing[other[j]]]];
      auto term = [&](double w, double mj) { return mj > 0 ? w / std::sqrt(mi * mj) : 0.0; };
      row[nd[j]] += pen * (term(1.0 / 3.0, mi) + term(1.0 / 3.0, mf) + term(1.0 / 6.0, mo) +
                           term(1.0 / 6.0, mof));
    }
  }
}

}  // namespace

void triangle_frequency(const EngineData& d, std::size_t t, double& omega2, double& xi) {
  const SolidConstants& s = d.solids[d.tris.material[t]];
  const Eigen::Matrix3d bbt = gradient_product(&d.tris.ref_inv[4 * t]);
  const Eigen::Matrix3d root = elasticity_sqrt(s.lambda, s.mu);
  const double alpha = d.tris.alpha[t], rho = s.rho * d.tris.density_factor(t);
  omega2 = 3.0 / rho * alpha * largest_eigenvalue(root * bbt * root);
  xi = 0;
  if (d.tris.eta[t] > 0 && omega2 > 0) {
    const Eigen::Vector3d v(1.0, 1.0, std::sqrt(0.5));
    const double c_max = 3.0 * d.tris.eta[t] * alpha / rho *
                         largest_eigenvalue(v.asDiagonal() * bbt * v.asDiagonal());
    xi = c_max / (2.0 * std::sqrt(omega2));
  }
}

double contact_triangle_omega2(const EngineData& d, std::size_t t) {
  const int* nd = &d.tris.nodes[3 * t];
  const int vertices[3] = {d.nodes.vertex[nd[0]], d.nodes.vertex[nd[1]], d.nodes.vertex[nd[2]]};
  const double h = smallest_altitude(d.nodes.vertex_pos.data(), vertices, d.tris.area0[t]);
  const double rho = d.materials[d.tris.material[t]].density * d.tris.density_factor(t);
  // A sticking friction spring is as stiff as the normal penalty.
  const double springs = d.contact.settings.friction ? 2.0 : 1.0;
  return springs * 36.0 * d.contact.penalty / (rho * h * h);
}

double contact_omega2(const EngineData& d) {
  const long nt = static_cast<long>(d.tris.size());
  double w2 = 0;
#pragma omp parallel for schedule(static) reduction(max : w2) num_threads(thread_count(d.threads))
  for (long t = 0; t < nt; ++t)
    if (d.tris.active[t]) w2 = std::max(w2, contact_triangle_omega2(d, std::size_t(t)));
  return w2;
}

double dashpot_max(const EngineData& d, std::size_t n) {
  const long b = d.nodes.bc(long(n));
  if (b < 0) return 0.0;
  const BoundaryRecord& r = d.bc_records[b];
  const double mean = 0.5 * (r.cxx + r.cyy), half = 0.5 * (r.cxx - r.cyy);
  return mean + std::sqrt(half * half + r.cxy * r.cxy);
}

void node_frequencies(const EngineData& d, bool with_contact, std::vector<double>& omega2,
                      std::vector<double>& xi, double* triangle_xi_max) {
  const std::size_t nn = d.nodes.size();
  const long nt = static_cast<long>(d.tris.size());
  std::vector<double> crack_w2(nn, 0.0), tri_w2(nt, 0.0), tri_xi(nt, 0.0);
  omega2.assign(nn, 0.0);
  xi.assign(nn, 0.0);
  // The triangles' eigenvalues in parallel, then their maxima per node in
  // order (a maximum is exact in any order: the same bits either way).
#pragma omp parallel for schedule(static) num_threads(thread_count(d.threads))
  for (long t = 0; t < nt; ++t) {
    if (!d.tris.active[t]) continue;
    triangle_frequency(d, std::size_t(t), tri_w2[t], tri_xi[t]);
    if (with_contact) tri_w2[t] += contact_triangle_omega2(d, std::size_t(t));
  }
  double xi_max = 0;
  for (long t = 0; t < nt; ++t) {
    if (!d.tris.active[t]) continue;
    xi_max = std::max(xi_max, tri_xi[t]);
    for (int k = 0; k < 3; ++k) {
      const int n = d.tris.nodes[3 * t + k];
      omega2[n] = std::max(omega2[n], tri_w2[t]);
      xi[n] = std::max(xi[n], tri_xi[t]);
    }
  }
  if (triangle_xi_max) *triangle_xi_max = xi_max;
  add_crack_rows(d, crack_w2);
  for (std::size_t n = 0; n < nn; ++n) {
    omega2[n] += crack_w2[n];
    // An absorbing dashpot C is explicit (-C v_old): its ratio c / (2 m omega)
    // shrinks the limit like viscous damping (c dt / m < 2 alone).
    const double c = dashpot_max(d, n), m = d.nodes.mass[n];
    if (c > 0 && m > 0 && omega2[n] > 0) xi[n] += c / (2.0 * m * std::sqrt(omega2[n]));
  }
}

void node_limits(const EngineData& d, std::vector<double>& limit, bool with_contact,
                 double* triangle_xi_max) {
  std::vector<double> w2, xi;
  node_frequencies(d, with_contact, w2, xi, triangle_xi_max);
  limit.assign(w2.size(), std::numeric_limits<double>::infinity());
  for (std::size_t n = 0; n < w2.size(); ++n)
    if (w2[n] > 0) limit[n] = damped_limit(d, std::sqrt(w2[n]), xi[n]);
}

}  // namespace rockfdem::fdem::detail

namespace rockfdem::fdem::detail {
namespace {

/// Deterministic pseudo-random start vector in [-1, 1] (splitmix64).
double start_value(std::uint64_t i) {
  std::uint64_t z = i + 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return double(z >> 11) / double(1ull << 52) - 1.0;
}

/// Unit direction (ex, ey) of each live crack element at the current
/// geometry, 0 for an inactive or broken one: fixed during the iteration, so
/// computed once rather than at every product (crack_frame, the expressions
/// the loop had: the same bits).
void crack_directions(const EngineData& d, std::vector<double>& dir) {
  const long nc = static_cast<long>(d.cracks.size());
  dir.assign(2 * nc, 0.0);
#pragma omp parallel for schedule(static) num_threads(thread_count(d.threads))
  for (long e = 0; e < nc; ++e) {
    if (!d.cracks.active[e] || d.cracks.state[e] == std::uint8_t(CrackState::kBroken)) continue;
    double n[2];
    crack_frame(d, std::size_t(e), &dir[2 * e], n);
  }
}

/// Linearised stiffness times u, into the slots `s` (same layout as the
/// force slots): small-strain CST at the reference configuration and the
/// crack elements' initial penalty slopes pn/h, pt/h along `dir`
/// (crack_directions). The vector is v * scale, each entry scaled as it is
/// read (the same product, so the same bits, as a scaled copy).
void apply_stiffness(const EngineData& d, const std::vector<double>& dir,
                     const std::vector<double>& v, double scale, std::vector<double>& s) {
  const auto u = [&](int j) { return v[j] * scale; };
  const long nt = static_cast<long>(d.tris.size()), nc = static_cast<long>(d.cracks.size());
#pragma omp parallel for schedule(static) num_threads(thread_count(d.threads))
  for (long t = 0; t < nt; ++t) {
    double* out = &s[6 * t];
    if (!d.tris.active[t]) {
      for (int k = 0; k < 6; ++k) out[k] = 0.0;
      continue;
    }
    const int* nd = &d.tris.nodes[3 * t];
    const double* g = &d.tris.ref_inv[4 * t];
    const double b[3] = {-(g[0] + g[2]), g[0], g[2]}, c[3] = {-(g[1] + g[3]), g[1], g[3]};
    double exx = 0, eyy = 0, gxy = 0;
    for (int k = 0; k < 3; ++k) {
      const double ux = u(2 * nd[k]), uy = u(2 * nd[k] + 1);
      exx += b[k] * ux;
      eyy += c[k] * uy;
      gxy += c[k] * ux + b[k] * uy;
    }
    const SolidConstants& m = d.solids[d.tris.material[t]];
    const double w = d.tris.alpha[t] * d.tris.area0[t];
    const double sxx = w * ((m.lambda + 2 * m.mu) * exx + m.lambda * eyy);
    const double syy = w * (m.lambda * exx + (m.lambda + 2 * m.mu) * eyy);
    const double sxy = w * m.mu * gxy;
    for (int k = 0; k < 3; ++k) {
      out[2 * k] = b[k] * sxx + c[k] * sxy;
      out[2 * k + 1] = c[k] * syy + b[k] * sxy;
    }
  }
  const std::size_t slot0 = d.crack_slot0();
#pragma omp parallel for schedule(static) num_threads(thread_count(d.threads))
  for (long e = 0; e < nc; ++e) {
    double* out = &s[2 * (slot0 + 2 * e)];  // nodes 0, 1; the gather negates them for 3, 2
    for (int k = 0; k < 4; ++k) out[k] = 0.0;
    if (!d.cracks.active[e] || d.cracks.state[e] == std::uint8_t(CrackState::kBroken)) continue;
    const int* nd = &d.cracks.nodes[4 * e];
    const double ex = dir[2 * e], ey = dir[2 * e + 1];
    const CrackConstants& k = d.crack_laws[d.cracks.material[e]];
    double o[2], sl[2];
    for (int end = 0; end < 2; ++end) {
      const int a = nd[end], f = nd[3 - end];
      const double dx = u(2 * a) - u(2 * f), dy = u(2 * a + 1) - u(2 * f + 1);
      o[end] = -dx * ey + dy * ex;
      sl[end] = dx * ex + dy * ey;
    }
    // Simpson: end weight h/6, half the midpoint's 2h/3; stresses pn o / h.
    for (int end = 0; end < 2; ++end) {
      const double on = (o[end] / 6.0 + (o[0] + o[1]) / 6.0) * k.pn;
      const double st = (sl[end] / 6.0 + (sl[0] + sl[1]) / 6.0) * k.pt;
      const double fx = st * ex - on * ey, fy = st * ey + on * ex;
      out[2 * end] = fx;
      out[2 * end + 1] = fy;
    }
  }
}

}  // namespace

/// 2 / omega reduced for damping. Viscous (ratio xi) and mass-proportional
/// (c m v, ratio c / (2 omega)) damping shrink it by sqrt(1 + xi^2) - xi.
/// Local damping raises a decelerating force to (1 + alpha) |f|, i.e. the
/// stiffness seen by the stiffest mode, so it divides the limit by
/// sqrt(1 + alpha).
/// The viscous ratio plus the mass-proportional one, c / (2 omega).
static double total_ratio(const EngineData& d, double omega, double xi_viscous) {
  return xi_viscous + d.damping.mass_proportional / (2.0 * omega);
}

double damped_limit(const EngineData& d, double omega, double xi_viscous) {
  const double xi = total_ratio(d, omega, xi_viscous);
  return 2.0 / omega * (std::sqrt(1.0 + xi * xi) - xi) / std::sqrt(1.0 + d.damping.local);
}

double damping_stiffening(const EngineData& d, double omega, double xi_viscous) {
  const double xi = total_ratio(d, omega, xi_viscous);
  return std::sqrt(1.0 + d.damping.local) / (std::sqrt(1.0 + xi * xi) - xi);
}

namespace {

/// Relative residual bound at which the largest Ritz value is taken: an
/// eigenvalue lies within that fraction of it (on the tunnel the largest
/// was within 0.02%, where the power iteration stopped 0.44% below).
constexpr double kLanczosTolerance = 3e-3;

/// Largest eigenvalue theta of the Lanczos tridiagonal (diagonal a,
/// off-diagonal b, b.size() == a.size() - 1) and the last component of its
/// eigenvector, whose product with the next off-diagonal bounds the
/// residual of theta's Ritz vector.
void top_ritz_pair(const std::vector<double>& a, const std::vector<double>& b, double& theta,
                   double& last) {
  const Eigen::Index n = static_cast<Eigen::Index>(a.size());
  Eigen::VectorXd diag = Eigen::Map<const Eigen::VectorXd>(a.data(), n);
  Eigen::VectorXd sub = Eigen::Map<const Eigen::VectorXd>(b.data(), n - 1);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver;
  solver.computeFromTridiagonal(diag, sub, Eigen::ComputeEigenvectors);
  theta = solver.eigenvalues()(n - 1);
  last = solver.eigenvectors()(n - 1, n - 1);
}

}  // namespace

double model_critical_dt(const EngineData& d, int max_iterations, double xi_max) {
  const long nn = static_cast<long>(d.nodes.size());
  const long n_blocks = (nn + kSumBlock - 1) / kSumBlock;
  // Lanczos on M^-1 K in the M inner product: q(j+1) beta(j) =
  // M^-1 K q(j) - alpha(j) q(j) - beta(j-1) q(j-1). Each vector is an array
  // times a scale applied as it is read (as the product reads it), so no
  // pass is spent on scaling; a massless node's entries stay 0.
  std::vector<double> q(2 * nn), prev(2 * nn, 0.0), s(d.slots.size()), partial(n_blocks);
  std::vector<double> dir;
  crack_directions(d, dir);
  const float* m = d.nodes.mass.data();
  for (long i = 0; i < 2 * nn; ++i) q[i] = m[i / 2] > 0 ? start_value(i) : 0.0;
  const double start2 = block_sum(nn, d.threads, [&](long i) {
    return m[i] * (q[2 * i] * q[2 * i] + q[2 * i + 1] * q[2 * i + 1]);
  });
  if (!(start2 > 0)) return std::numeric_limits<double>::infinity();
  double q_scale = 1.0 / std::sqrt(start2), prev_scale = 0.0, beta = 0.0, lambda = 0.0;
  std::vector<double> alphas, betas;
  for (int it = 0; it < max_iterations; ++it) {
    apply_stiffness(d, dir, q, q_scale, s);
    // prev <- M^-1 K q - beta prev; block partials of q.K q (fixed order).
#pragma omp parallel for schedule(static) num_threads(thread_count(d.threads))
    for (long b = 0; b < n_blocks; ++b) {
      double qkq = 0;
      for (long i = b * kSumBlock; i < std::min(nn, (b + 1) * kSumBlock); ++i) {
        if (m[i] <= 0) continue;
        double fx = 0, fy = 0;
        gather_slots(d.nodes, s.data(), std::size_t(i), fx, fy);
        qkq += q[2 * i] * q_scale * fx + q[2 * i + 1] * q_scale * fy;
        prev[2 * i] = fx / m[i] - beta * (prev[2 * i] * prev_scale);
        prev[2 * i + 1] = fy / m[i] - beta * (prev[2 * i + 1] * prev_scale);
      }
      partial[b] = qkq;
    }
    double alpha = 0;
    for (long b = 0; b < n_blocks; ++b) alpha += partial[b];
      // prev <- prev - alpha q; block partials of its M norm.
#pragma omp parallel for schedule(static) num_threads(thread_count(d.threads))
    for (long b = 0; b < n_blocks; ++b) {
      double norm2 = 0;
      for (long i = b * kSumBlock; i < std::min(nn, (b + 1) * kSumBlock); ++i) {
        if (m[i] <= 0) continue;
        prev[2 * i] -= alpha * (q[2 * i] * q_scale);
        prev[2 * i + 1] -= alpha * (q[2 * i + 1] * q_scale);
        norm2 += m[i] * (prev[2 * i] * prev[2 * i] + prev[2 * i + 1] * prev[2 * i + 1]);
      }
      partial[b] = norm2;
    }
    double norm2 = 0;
    for (long b = 0; b < n_blocks; ++b) norm2 += partial[b];
    alphas.push_back(alpha);
    beta = std::sqrt(norm2);
    double last = 1.0;
    top_ritz_pair(alphas, betas, lambda, last);
    // An invariant subspace, or a Ritz value whose residual is within
    // kLanczosTolerance of it: the largest eigenvalue to that accuracy.
    if (!(beta > 0) || beta * std::fabs(last) <= kLanczosTolerance * lambda) break;
    betas.push_back(beta);
    q.swap(prev);  // q(j+1) = prev / beta; prev becomes q(j)
    prev_scale = q_scale;
    q_scale = 1.0 / beta;
  }
  if (!(lambda > 0)) return std::numeric_limits<double>::infinity();
  return damped_limit(d, std::sqrt(lambda), xi_max);
}

double critical_dt(const EngineData& d) {
  // The Lanczos estimate approaches omega_max from below (dt from above); the
  // element bound is safe but can be conservative by tens of percent. Take
  // the Lanczos estimate, never beyond 1.5 times the bound, and never beyond
  // the bound of a node with an absorbing dashpot (which the iteration
  // does not see).
  std::vector<double> limit;
  double xi_max = 0;
  node_limits(d, limit, false, &xi_max);
  double bound = std::numeric_limits<double>::infinity(), dashpots = bound;
  for (std::size_t n = 0; n < limit.size(); ++n) {
    bound = std::min(bound, limit[n]);
    if (dashpot_max(d, n) > 0) dashpots = std::min(dashpots, limit[n]);
  }
  return std::min({model_critical_dt(d, 200, xi_max), 1.5 * bound, dashpots});
}

}  // namespace rockfdem::fdem::detail
