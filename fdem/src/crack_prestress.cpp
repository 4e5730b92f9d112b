// Crack elements that start carrying the initial stress (see the header).
//
// At each mesh vertex v the engine nodes there are joined by crack-element
// ends: end 0 of element c joins its nodes 0 and 3, end 1 joins 1 and 2. Let
// T be the force an end passes to its first node (the second gets -T) and r_n
// the force node n needs from the cracks, -(triangle forces + external load).
// Balance at v is A T = r with A the node-end incidence (+1 first, -1
// second). Around an interior vertex the ends form a cycle, so many T
// balance; we take the one closest to the prior T0 of the uniform traction
// ((sA + sB)/2) n: T = T0 + A^T l with (A A^T) l = r - A T0 (a small graph
// Laplacian, solved by a complete orthogonal decomposition: the minimum-norm
// least-squares solution, which also spreads a reaction at a supported vertex
// like the unsplit mesh does). For a uniform field r = A T0 and T = T0.
//
// End forces become per-point tractions: with Simpson weights h/6, h/3 (half
// the midpoint's 2h/3) and a midpoint traction (t0 + t1)/2, the force on
// node 0 is -(h/3 t0 + h/6 t1), so t0 = (2 F1 - 4 F0)/h and t1 = (2 F0 - 4 F1)/h.
// Each point's (sigma, tau) = (t.n, t.e) is turned into the relative
// displacement at which the undamaged law carries it, and the offset makes
// that the current state.
#include "crack_prestress.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "crack_elements.hpp"
#include "node_update.hpp"
#include "rockfdem/fdem/crack_law.hpp"
#include "strength_heterogeneity.hpp"
#include "triangle_force.hpp"

namespace rockfdem::fdem::detail {
namespace {

/// Mean of the initial stresses of the element's two triangles, times n.
void mean_traction(const EngineData& d, std::size_t c, const double n[2], double t[2]) {
  const float* a = &d.tris.sigma0[3 * d.crack_triangle(c, 0)];
  const float* b = &d.tris.sigma0[3 * d.crack_triangle(c, 1)];
  const double sxx = 0.5 * (double(a[0]) + b[0]), syy = 0.5 * (double(a[1]) + b[1]);
  const double sxy = 0.5 * (double(a[2]) + b[2]);
  t[0] = sxx * n[0] + sxy * n[1];
  t[1] = sxy * n[0] + syy * n[1];
}

/// Ends of active elements grouped by mesh vertex (CSR); an end is 2c + k.
void ends_by_vertex(const EngineData& d, std::vector<int>& start, std::vector<int>& ends) {
  const std::size_t nv = d.vertex_node_start.size() - 1, nc = d.cracks.size();
  start.assign(nv + 1, 0);
  auto vertex_of = [&](std::size_t end) {
    return d.nodes.vertex[d.cracks.nodes[4 * (end / 2) + end % 2]];
  };
  for (std::size_t end = 0; end < 2 * nc; ++end)
    if (d.cracks.active[end / 2]) ++start[vertex_of(end) + 1];
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  ends.resize(start[nv]);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (std::size_t end = 0; end < 2 * nc; ++end)
    if (d.cracks.active[end / 2]) ends[fill[vertex_of(end)]++] = static_cast<int>(end);
}

/// Solves the balance at one vertex; T holds the prior on entry (2 per end).
void balance_vertex(const EngineData& d, int v, const int* ends, int n_ends,
                    const std::vector<double>& need, std::vector<double>& T) {
  const int n0 = d.vertex_node_start[v], k = d.vertex_node_start[v + 1] - n0;
  auto local = [&](int node) {
    for (int i = 0; i < k; ++i)
      if (d.vertex_nodes[n0 + i] == node) return i;
    return -1;
  };
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(k, n_ends);
  for (int j = 0; j < n_ends; ++j) {
    const int c = ends[j] / 2, end = ends[j] % 2;
    A(local(d.cracks.nodes[4 * c + end]), j) = 1.0;
    A(local(d.cracks.nodes[4 * c + 3 - end]), j) = -1.0;
  }
  Eigen::MatrixXd b(k, 2), t0(n_ends, 2);
  for (int i = 0; i < k; ++i)
    for (int x = 0; x < 2; ++x) b(i, x) = need[2 * d.vertex_nodes[n0 + i] + x];
  for (int j = 0; j < n_ends; ++j)
    for (int x = 0; x < 2; ++x) t0(j, x) = T[2 * ends[j] + x];
  b -= A * t0;
  const Eigen::MatrixXd lambda =
      Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(A * A.transpose()).solve(b);
  const Eigen::MatrixXd t = t0 + A.transpose() * lambda;
  for (int j = 0; j < n_ends; ++j)
    for (int x = 0; x < 2; ++x) T[2 * ends[j] + x] = t(j, x);
}

/// Offsets of element c (length h) such that its three points carry the
/// normal and shear stresses st (3 x (sigma, tau)) at the openings and
/// slips `cur`. Returns the clipped point count.
long offsets_carrying(EngineData& d, std::size_t c, double h, const double st[6],
                      const double cur[6]) {
  const CrackConstants k = crack_constants(d, c);
  long clipped = 0;
  for (int i = 0; i < 3; ++i) {
    double o, s;
    clipped += pre_peak_displacement(k, st[2 * i], st[2 * i + 1], h, o, s);
    store_offsets(cur[2 * i], cur[2 * i + 1], o, s, &d.cracks.offset[6 * c + 2 * i]);
  }
  return clipped;
}

/// Offsets of element c such that its three points carry tractions tp
/// (3 x (tx, ty)) at the openings and slips `cur`. Returns the clipped
/// point count.
long set_point_offsets(EngineData& d, std::size_t c, const double tp[6], const double cur[6]) {
  double e[2], n[2];
  const double h = crack_frame(d, c, e, n);
  double st[6];
  for (int i = 0; i < 3; ++i) {
    st[2 * i] = tp[2 * i] * n[0] + tp[2 * i + 1] * n[1];
    st[2 * i + 1] = tp[2 * i] * e[0] + tp[2 * i + 1] * e[1];
  }
  return offsets_carrying(d, c, h, st, cur);
}

}  // namespace

long prestress_cracks(EngineData& d) {
  const std::size_t nc = d.cracks.size(), nn = d.nodes.size();
  if (nc == 0 || d.tris.sigma0.empty()) return 0;
  if (d.masses_dirty) refresh_nodes(d);  // masses, external loads, crack activity
  triangle_forces(d);                    // an inverted start is reported by the first step
  std::vector<double> need(2 * nn);
  for (std::size_t i = 0; i < nn; ++i) {
    double fx, fy;
    node_force(d, i, fx, fy);  // crack slots are still zero
    need[2 * i] = -fx;
    need[2 * i + 1] = -fy;
  }
  // Prior: each end passes (h/2) of the uniform traction, on the first face -(h/2) t.
  std::vector<double> T(4 * nc, 0.0);
  for (std::size_t c = 0; c < nc; ++c) {
    if (!d.cracks.active[c]) continue;
    double e[2], n[2], t[2];
    const double h = crack_frame(d, c, e, n);
    mean_traction(d, c, n, t);
    for (int end = 0; end < 2; ++end)
      for (int x = 0; x < 2; ++x) T[4 * c + 2 * end + x] = -0.5 * h * t[x];
  }
  std::vector<int> start, ends;
  ends_by_vertex(d, start, ends);
  for (std::size_t v = 0; v + 1 < start.size(); ++v)
    if (start[v + 1] > start[v])
      balance_vertex(d, static_cast<int>(v), &ends[start[v]], start[v + 1] - start[v], need, T);
  if (d.cracks.offset.empty()) d.cracks.offset.assign(6 * nc, 0.0);
  long clipped = 0;
  for (std::size_t c = 0; c < nc; ++c) {
    if (!d.cracks.active[c]) continue;
    double e[2], n[2];
    const double h = crack_frame(d, c, e, n);
    const double* f0 = &T[4 * c];
    const double* f1 = &T[4 * c + 2];
    double tp[6], cur[6];
    crack_point_openings(d, c, cur);
    for (int x = 0; x < 2; ++x) {
      tp[x] = (2.0 * f1[x] - 4.0 * f0[x]) / h;
      tp[4 + x] = (2.0 * f0[x] - 4.0 * f1[x]) / h;
      tp[2 + x] = 0.5 * (tp[x] + tp[4 + x]);
    }
    clipped += set_point_offsets(d, c, tp, cur);
  }
  return clipped;
}

int carry_point_stresses(EngineData& d, std::size_t c, const double st[6]) {
  if (d.cracks.offset.empty()) d.cracks.offset.assign(6 * d.cracks.size(), 0.0);
  double cur[6];
  const double h = crack_point_openings(d, c, cur);
  return static_cast<int>(offsets_carrying(d, c, h, st, cur));
}

}  // namespace rockfdem::fdem::detail
