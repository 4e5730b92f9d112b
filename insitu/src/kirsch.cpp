// Closed forms of fdem-reference.md section 5 and the comparison of a solved
// field with them. No deal.II here: this file is plain arithmetic on the mesh
// record, so workflows/ and the tests can use it cheaply.
#include <cmath>
#include <set>

#include "rockfdem/error.hpp"
#include "rockfdem/insitu/constants.hpp"
#include "rockfdem/insitu/insitu.hpp"

namespace rockfdem::insitu {

namespace {

/// Polar components (tension positive) of the Kirsch field at (r, t), t
/// measured from the sH direction.
struct Polar {
  double srr, stt, srt;
};

Polar kirsch_polar(const KirschCase& k, double r, double t) {
  const double p = 0.5 * (k.sH + k.sV);  // mean, compression positive
  const double q = 0.5 * (k.sH - k.sV);  // deviator
  const double a2 = k.a * k.a / (r * r);
  const double a4 = a2 * a2;
  const double c2 = std::cos(2 * t), s2 = std::sin(2 * t);
  // Reference section 5 is written compression positive: negate for output.
  return {-(p * (1 - a2) + q * (1 - 4 * a2 + 3 * a4) * c2), -(p * (1 + a2) - q * (1 + 3 * a4) * c2),
          -(-q * (1 + 2 * a2 - 3 * a4) * s2)};
}

/// Cartesian stress -> polar components at polar angle phi (from +x).
Polar to_polar(const Stress& s, double phi) {
  const double c = std::cos(phi), n = std::sin(phi);
  return {s.sxx * c * c + s.syy * n * n + 2 * s.sxy * n * c,
          s.sxx * n * n + s.syy * c * c - 2 * s.sxy * n * c,
          (s.syy - s.sxx) * n * c + s.sxy * (c * c - n * n)};
}

}  // namespace

Stress kirsch_stress(const KirschCase& k, double x, double y) {
  const double r = std::hypot(x, y);
  const double phi = std::atan2(y, x);
  const Polar p = kirsch_polar(k, r, phi - k.angle_deg * kPi / 180);
  const double c = std::cos(phi), n = std::sin(phi);
  Stress s;
  s.sxx = p.srr * c * c + p.stt * n * n - 2 * p.srt * n * c;
  s.syy = p.srr * n * n + p.stt * c * c + 2 * p.srt * n * c;
  s.sxy = (p.srr - p.stt) * n * c + p.srt * (c * c - n * n);
  // Plane strain from rest: the out-of-plane stress follows the in-plane sum.
  s.szz = k.nu * (s.sxx + s.syy);
  return s;
}

double kirsch_radial_displacement(const KirschCase& k, double r, double theta) {
  const double G = k.E / (2 * (1 + k.nu));
  const double t = theta - k.angle_deg * kPi / 180;
  const double a2 = k.a * k.a / (r * r);
  return -(k.a * k.a / (4 * G * r)) *
         ((k.sH + k.sV) + (k.sH - k.sV) * (4 * (1 - k.nu) - a2) * std::cos(2 * t));
}

double core_softening_wall_displacement(double alpha, double p, double a, double E, double nu) {
  const double mu = E / (2 * (1 + nu));
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double K = lambda + mu;  // plane-strain bulk modulus
  const double S = -p;           // tension positive
  return S * a / (2 * K) * ((K + mu) / (alpha * K + mu) - 1);
}

KirschComparison compare_kirsch(const mesh::Mesh& mesh, const InsituField& field,
                                const KirschCase& k) {
  if (field.stress.size() != mesh.n_triangles() || field.ux.size() != mesh.n_vertices())
    throw InputError("compare_kirsch: the field does not belong to this mesh (" +
                     std::to_string(field.stress.size()) + " stresses for " +
                     std::to_string(mesh.n_triangles()) + " triangles)");
  if (!(k.a > 0) || !(k.E > 0))
    throw InputError("compare_kirsch: hole radius and E must be positive");

  KirschComparison out;

  // 1. Stresses: area-weighted L2 over the annulus a <= r <= 5a, each
  //    triangle's constant FE stress against the exact stress at its centroid.
  double num = 0, den = 0;
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    if (!field.active[t]) continue;
    const auto& tri = mesh.triangles[t];
    const double xa = mesh.x[tri[0]], ya = mesh.y[tri[0]];
    const double xb = mesh.x[tri[1]], yb = mesh.y[tri[1]];
    const double xc = mesh.x[tri[2]], yc = mesh.y[tri[2]];
    const double cx = (xa + xb + xc) / 3, cy = (ya + yb + yc) / 3;
    const double r = std::hypot(cx, cy);
    if (r < k.a || r > 5 * k.a) continue;
    const double area = 0.5 * std::abs((xb - xa) * (yc - ya) - (xc - xa) * (yb - ya));
    const Stress e = kirsch_stress(k, cx, cy);
    const Stress& h = field.stress[t];
    const double dxx = h.sxx - e.sxx, dyy = h.syy - e.syy, dxy = h.sxy - e.sxy;
    num += area * (dxx * dxx + dyy * dyy + 2 * dxy * dxy);
    den += area * (e.sxx * e.sxx + e.syy * e.syy + 2 * e.sxy * e.sxy);

    const double phi = std::atan2(cy, cx);
    const auto ph = to_polar(h, phi), pe = to_polar(e, phi);
    out.rows.push_back(
        {static_cast<int>(t), cx, cy, r, phi, ph.srr, ph.stt, ph.srt, pe.srr, pe.stt, pe.srt});
  }
  out.n_triangles = out.rows.size();
  out.stress_rel_l2 = den > 0 ? std::sqrt(num / den) : 0;

  // 2. Wall displacement: radial component at the vertices on r = a.
  std::set<int> wall;
  for (const auto& e : mesh.edges)
    if (e.tag == mesh::kExcavation) {
      wall.insert(e.a);
      wall.insert(e.b);
    }
  if (wall.empty())
    for (std::size_t v = 0; v < mesh.n_vertices(); ++v)
      if (std::abs(std::hypot(mesh.x[v], mesh.y[v]) - k.a) < 1e-6 * k.a)
        wall.insert(static_cast<int>(v));
  double unum = 0, uden = 0, sum_h = 0, sum_e = 0;
  for (const int v : wall) {
    const double r = std::hypot(mesh.x[v], mesh.y[v]);
    const double phi = std::atan2(mesh.y[v], mesh.x[v]);
    const double ur_h = (field.ux[v] * mesh.x[v] + field.uy[v] * mesh.y[v]) / r;
    const double ur_e = kirsch_radial_displacement(k, r, phi);
    unum += (ur_h - ur_e) * (ur_h - ur_e);
    uden += ur_e * ur_e;
    sum_h += ur_h;
    sum_e += ur_e;
  }
  out.n_wall_vertices = wall.size();
  if (!wall.empty()) {
    out.wall_ur_rel_l2 = uden > 0 ? std::sqrt(unum / uden) : 0;
    out.wall_ur_mean = sum_h / wall.size();
    out.wall_ur_mean_exact = sum_e / wall.size();
  }
  return out;
}

}  // namespace rockfdem::insitu
