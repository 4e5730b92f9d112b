// Bolt steel calibrated to the strip of marked triangles (bolt_steel.hpp).
#include "rockfdem/fdem/bolt_steel.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "rockfdem/error.hpp"

namespace rockfdem::fdem {
namespace {

/// The crack material of the steel, every stress scaled by f.
Material steel_crack_material(const BoltSteel& s, double f, double e_tri, double open_range) {
  Material m;
  m.density = 7850;
  m.young = f * e_tri;
  m.poisson = 0;
  m.crack_law = CrackLaw::kBoltSteel;
  m.yield_strength = f * s.yield_strength;
  m.ultimate_strength = f * s.ultimate_strength;
  m.shear_yield_strength = f * s.shear_yield_strength;
  // Rock-law fields: only the "weaker material" choice at construction reads them.
  m.tensile_strength = m.yield_strength;
  m.cohesion = m.shear_yield_strength;
  m.gf_I = 0.5 * (m.yield_strength + m.ultimate_strength) * open_range;  // eq. 14
  m.gf_II = f * s.gf_II;
  m.normal_penalty = m.tangential_penalty = s.penalty_factor * f * e_tri;
  return m;
}

void check_steel(const BoltSteel& s, double row_spacing) {
  const bool ok = s.young > 0 && s.yield_strength > 0 && s.ultimate_strength > s.yield_strength &&
                  s.tangent_modulus > 0 && s.tangent_modulus < s.young &&
                  s.shear_yield_strength > 0 && s.gf_II > 0 && s.penalty_factor > 0 &&
                  row_spacing > 0;
  if (!ok)
    throw InputError(
        "fdem bolts: steel needs E > 0, 0 < sigma_y < sigma_u, 0 < ET < E, tau_y > 0, "
        "GfII > 0, penalty factor > 0 and row spacing > 0 (got E " +
        std::to_string(s.young) + ", sigma_y " + std::to_string(s.yield_strength) + ", sigma_u " +
        std::to_string(s.ultimate_strength) + ", ET " + std::to_string(s.tangent_modulus) +
        ", s_b " + std::to_string(row_spacing) + ")");
}

}  // namespace

BoltStrip bolt_strip(const ModelInput& in, const BoltMarks& marks, int b, const Bolt& bolt) {
  BoltStrip strip;
  strip.length = std::hypot(bolt.b[0] - bolt.a[0], bolt.b[1] - bolt.a[1]);
  const double ux = (bolt.b[0] - bolt.a[0]) / strip.length;
  const double uy = (bolt.b[1] - bolt.a[1]) / strip.length;
  std::map<std::pair<int, int>, int> uses;
  for (int t : marks.triangles[b]) {
    if (marks.owner[t] != b) continue;
    const auto& v = in.triangles[t];
    strip.area += 0.5 * std::fabs((in.x[v[1]] - in.x[v[0]]) * (in.y[v[2]] - in.y[v[0]]) -
                                  (in.y[v[1]] - in.y[v[0]]) * (in.x[v[2]] - in.x[v[0]]));
    for (int k = 0; k < 3; ++k) {
      const int p = v[k], q = v[(k + 1) % 3];
      ++uses[{std::min(p, q), std::max(p, q)}];
    }
  }
  for (const auto& [edge, n] : uses) {
    if (n != 2) continue;
    const double ex = in.x[edge.second] - in.x[edge.first];
    const double ey = in.y[edge.second] - in.y[edge.first];
    const double h = std::hypot(ex, ey);
    const double cos_e = std::fabs(ex * ux + ey * uy) / h;
    const double cos_n = std::fabs(-ey * ux + ex * uy) / h;
    strip.cracks.push_back({h, cos_n, cos_e});
  }
  strip.width = strip.area / strip.length;
  return strip;
}

double bolt_scale(const Bolt& bolt, const BoltStrip& strip, double row_spacing) {
  return bolt.diameter / strip.width / row_spacing;
}

BoltSteelModel bolt_steel_model(const BoltSteel& s, double row_spacing, const Bolt& bolt,
                                const BoltStrip& strip) {
  check_steel(s, row_spacing);
  if (!(strip.area > 0))
    throw InputError("fdem bolts: a bolt marks no triangle; check its position against the mesh");
  BoltSteelModel m;
  m.scale = bolt_scale(bolt, strip, row_spacing);
  const double r = s.shear_yield_strength / s.yield_strength;
  double sum_g = 0, sum_q = 0;
  for (const StripCrack& c : strip.cracks) {
    const double shear = c.cos_n * c.cos_e;  // tau / sigma on this crack
    if (shear >= r)
      throw InputError("fdem bolts: a crack element inside a bolt strip lies at " +
                       std::to_string(std::acos(std::min(1.0, c.cos_n)) * 57.29577951308232) +
                       " deg to the bolt's cross-section and would fail in shear (tau_y / "
                       "sigma_y = " +
                       std::to_string(r) +
                       ") before the bolt yields; mesh the strip with edges across the bolt");
    const double opening = c.cos_n * c.cos_n * (1 - std::sqrt(1 - c.cos_n * c.cos_n));
    const double slip = r * shear * (1 - std::sqrt(1 - shear / r));
    sum_g += c.length * c.length * (opening + slip);
    if (c.cos_n * c.cos_n >= 0.5) sum_q += c.length * c.cos_n * c.cos_n;
  }
  if (!(sum_q > 0))
    throw InputError(
        "fdem bolts: a bolt strip has no crack element across its axis, so it "
        "could not yield; allow fracture in its triangles (or refine the mesh)");
  m.yield_flexibility = 2 * sum_g / strip.area;
  m.transverse_density = sum_q / strip.area;
  const double e_tri = s.young * (1 + m.yield_flexibility / s.penalty_factor);
  const double hardening = 1 / s.tangent_modulus - 1 / e_tri;
  const double open_range =
      (s.ultimate_strength - s.yield_strength) * hardening / m.transverse_density;
  m.triangle_modulus = m.scale * e_tri;
  m.crack = steel_crack_material(s, m.scale, e_tri, open_range);
  return m;
}

Material row_spacing_scaled_steel(const BoltSteel& s, double row_spacing, double crack_spacing) {
  check_steel(s, row_spacing);
  const double open_range = crack_spacing * (s.ultimate_strength - s.yield_strength) *
                            (1 / s.tangent_modulus - 1 / s.young);
  return steel_crack_material(s, 1 / row_spacing, s.young, open_range);
}

}  // namespace rockfdem::fdem
