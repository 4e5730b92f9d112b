// Stored energy of contact (the energy balance's contact_elastic term).
//
// Normal penalty. The forces of contact_force.cpp on the contactor C of a
// pair (C, T) add up to p int_{C n T} (grad phi_C - grad phi_T) dA (both
// roles; the boundary integrals become area integrals by the divergence
// theorem because each potential vanishes on its own triangle's edges).
// For a rigid motion of either triangle that is minus the gradient of
//   E = p int_{C n T} (phi_C + phi_T) dA,
// the potential of Munjiza and Andrews' contact, evaluated here exactly:
// phi_A = 3 lambda_k on the sub-triangle of A between its centroid and the
// edge opposite corner k, so each sub-triangle clips the other triangle to a
// convex polygon on which phi_A is linear, and a linear function integrates
// to the polygon's area times its value at the polygon's centroid.
// (Deforming or rotating triangles make the force only approximately the
// gradient of E: see docs/engine.md, "Energy balance".)
//
// Friction springs. Each spring F_t of stiffness k_t = 3 p L_in / H (the
// normal stiffness of its edge's overlap, as in contact_force.cpp) stores
// F_t^2 / (2 k_t).
#include <algorithm>
#include <cmath>

#include "contact.hpp"
#include "engine_data.hpp"
#include "parallel.hpp"

namespace rockfdem::fdem::detail {
namespace {

struct Tri {
  double x[3], y[3];
};

/// Convex polygon of at most 3 + 3 vertices (a triangle clipped by three
/// half-planes), with room to spare.
struct Polygon {
  double x[12], y[12];
  int n = 0;
};

/// Keeps the part of `p` left of the directed line a -> b.
void clip_left(Polygon& p, double ax, double ay, double bx, double by) {
  Polygon out;
  const double ux = bx - ax, uy = by - ay;
  for (int i = 0; i < p.n; ++i) {
    const int j = (i + 1) % p.n;
    const double si = ux * (p.y[i] - ay) - uy * (p.x[i] - ax);
    const double sj = ux * (p.y[j] - ay) - uy * (p.x[j] - ax);
    if (si >= 0.0) {
      out.x[out.n] = p.x[i];
      out.y[out.n++] = p.y[i];
    }
    if ((si >= 0.0) != (sj >= 0.0)) {
      const double r = si / (si - sj);
      out.x[out.n] = p.x[i] + r * (p.x[j] - p.x[i]);
      out.y[out.n++] = p.y[i] + r * (p.y[j] - p.y[i]);
    }
  }
  p = out;
}

/// int_{A n B} phi_A dA.
double potential_integral(const Tri& a, const Tri& b) {
  const double two_a =
      (a.x[1] - a.x[0]) * (a.y[2] - a.y[0]) - (a.x[2] - a.x[0]) * (a.y[1] - a.y[0]);
  if (!(two_a > 0.0)) return 0.0;
  const double gx = (a.x[0] + a.x[1] + a.x[2]) / 3.0, gy = (a.y[0] + a.y[1] + a.y[2]) / 3.0;
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;  // sub-triangle (i, j, centroid), ccw
    Polygon p;
    p.n = 3;
    for (int m = 0; m < 3; ++m) {
      p.x[m] = b.x[m];
      p.y[m] = b.y[m];
    }
    clip_left(p, a.x[i], a.y[i], a.x[j], a.y[j]);
    clip_left(p, a.x[j], a.y[j], gx, gy);
    clip_left(p, gx, gy, a.x[i], a.y[i]);
    if (p.n < 3) continue;
    double area2 = 0.0, cx = 0.0, cy = 0.0;
    for (int m = 0; m < p.n; ++m) {
      const int q = (m + 1) % p.n;
      const double cross = p.x[m] * p.y[q] - p.x[q] * p.y[m];
      area2 += cross;
      cx += (p.x[m] + p.x[q]) * cross;
      cy += (p.y[m] + p.y[q]) * cross;
    }
    if (!(area2 > 0.0)) continue;
    cx /= 3.0 * area2;
    cy /= 3.0 * area2;
    // lambda_k at the centroid: the area of (centroid, i, j) over A's.
    const double lambda = ((a.x[i] - cx) * (a.y[j] - cy) - (a.x[j] - cx) * (a.y[i] - cy)) / two_a;
    sum += 0.5 * area2 * 3.0 * lambda;
  }
  return sum;
}

/// Stored energy of the three friction springs of contactor c's edges on
/// target t: F^2 / (2 k_t) with k_t = 3 p L_in / H.
double spring_energy(const Tri& c, const Tri& t, double p, const double* spring) {
  const double two_a =
      (t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) - (t.x[2] - t.x[0]) * (t.y[1] - t.y[0]);
  if (!(two_a > 0.0)) return 0.0;
  double longest = 0;
  for (int k = 0; k < 3; ++k)
    longest = std::max(longest, std::hypot(t.x[(k + 1) % 3] - t.x[k], t.y[(k + 1) % 3] - t.y[k]));
  const double h_t = two_a / longest;
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    if (spring[k] == 0.0) continue;
    const int a = k, b = (k + 1) % 3;
    // Part of the edge inside t, from the barycentric coordinates of its ends.
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, m = (i + 2) % 3;
      auto lam = [&](double px, double py) {
        return ((t.x[j] - px) * (t.y[m] - py) - (t.x[m] - px) * (t.y[j] - py)) / two_a;
      };
      const double la = lam(c.x[a], c.y[a]), lb = lam(c.x[b], c.y[b]);
      if (la < 0.0 && lb < 0.0)
        hi = lo;
      else if (la < 0.0)
        lo = std::max(lo, la / (la - lb));
      else if (lb < 0.0)
        hi = std::min(hi, la / (la - lb));
    }
    if (!(hi > lo)) continue;
    const double len = std::hypot(c.x[b] - c.x[a], c.y[b] - c.y[a]);
    const double k_t = 3.0 * p * len * (hi - lo) / h_t;
    sum += spring[k] * spring[k] / (2.0 * k_t);
  }
  return sum;
}

Tri corners(const EngineData& d, int t, const Placement& at) {
  Tri r;
  for (int k = 0; k < 3; ++k) {
    const int n = d.tris.nodes[3 * t + k];
    r.x[k] = at.x(n);
    r.y[k] = at.y(n);
  }
  return r;
}

}  // namespace

double contact_pair_energy(const EngineData& d, int ta, int tb, const double* springs,
                           const Placement& at) {
  if (!d.tris.active[ta] || !d.tris.active[tb]) return 0.0;
  const Tri a = corners(d, ta, at), b = corners(d, tb, at);
  if (std::max({a.x[0], a.x[1], a.x[2]}) < std::min({b.x[0], b.x[1], b.x[2]}) ||
      std::max({b.x[0], b.x[1], b.x[2]}) < std::min({a.x[0], a.x[1], a.x[2]}) ||
      std::max({a.y[0], a.y[1], a.y[2]}) < std::min({b.y[0], b.y[1], b.y[2]}) ||
      std::max({b.y[0], b.y[1], b.y[2]}) < std::min({a.y[0], a.y[1], a.y[2]}))
    return 0.0;  // apart (most pairs within the buffer)
  const double p = d.contact.penalty;
  double e = p * (potential_integral(a, b) + potential_integral(b, a));
  if (d.contact.settings.friction && springs)
    e += spring_energy(a, b, p, springs) + spring_energy(b, a, p, springs + 3);
  return e;
}

double contact_pair_energy(const EngineData& d, std::size_t q, const Placement& at) {
  const ContactData& c = d.contact;
  return contact_pair_energy(d, c.pairs[q][0], c.pairs[q][1],
                             c.friction.empty() ? nullptr : &c.friction[6 * q], at);
}

double contact_energy(const EngineData& d, const Placement& at) {
  if (!d.contact_on) return 0.0;
  return block_sum(static_cast<long>(d.contact.pairs.size()), d.threads,
                   [&](long q) { return contact_pair_energy(d, q, at); });
}

}  // namespace rockfdem::fdem::detail
