#include "scene/scene_checks.hpp"

#include <cmath>
#include <cstdio>

#include "rockfdem/mesh/outline.hpp"
#include "rockfdem/workflows/scene_schema.hpp"
#include "scene/stage_damping.hpp"

namespace rockfdem::workflows::detail {
namespace {

// To the millimetre, so that a point found by a search reads 0, not 1e-15.
std::string point_text(double x, double y) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(x, y) = (%.3g, %.3g) m", std::round(x * 1e3) / 1e3 + 0.0,
                std::round(y * 1e3) / 1e3 + 0.0);
  return buf;
}

std::string metres(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g m", v);
  return buf;
}

[[noreturn]] void refuse(const RawScene& raw, const BoltPlacement& b, bool at_end,
                         const std::string& problem) {
  const std::string& key = at_end ? b.end_key : b.collar_key;
  fail_key(raw, key, raw.root.at_path(key).node(), b.label + " " + problem);
}

// Signed distance to the opening's outline: negative inside the opening.
double depth(const mesh::Outline& o, double x, double y) {
  const double d = mesh::distance_to_outline(o, x, y);
  return mesh::inside_outline(o, x, y) ? -d : d;
}

// The point of the bolt (as a fraction of its length) deepest inside the
// opening. The signed distance to a convex outline is convex along a line,
// so a golden-section search finds its minimum.
double deepest_along(const mesh::Outline& o, const std::array<double, 4>& s) {
  const auto f = [&](double t) {
    return depth(o, s[0] + t * (s[2] - s[0]), s[1] + t * (s[3] - s[1]));
  };
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double a = 0, b = 1;
  for (int i = 0; i < 80; ++i) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (f(c) < f(d))
      b = d;
    else
      a = c;
  }
  double best = 0.5 * (a + b);
  for (double end : {0.0, 1.0})
    if (f(end) < f(best)) best = end;
  return best;
}

void check_in_domain(const RawScene& raw, const mesh::DomainSpec& d, const BoltPlacement& b) {
  for (int k = 0; k < 4; k += 2) {
    const double x = b.seg[k], y = b.seg[k + 1];
    if (std::abs(x - d.center_x) < d.width / 2 && std::abs(y - d.center_y) < d.height / 2) continue;
    refuse(raw, b, k > 0,
           std::string(k ? "ends" : "starts") + " at " + point_text(x, y) +
               ", outside the rock domain; allowed: x from " + metres(d.center_x - d.width / 2) +
               " to " + metres(d.center_x + d.width / 2) + ", y from " +
               metres(d.center_y - d.height / 2) + " to " + metres(d.center_y + d.height / 2));
  }
}

}  // namespace

double collar_tolerance(const mesh::MeshSpec& m) { return std::max(0.5 * m.size.size_near, 0.05); }

void check_bolt_placement(const RawScene& raw, const mesh::MeshSpec& m, const BoltPlacement& b) {
  const auto& s = b.seg;
  if (!(std::hypot(s[2] - s[0], s[3] - s[1]) > 0)) refuse(raw, b, true, "has zero length");
  check_in_domain(raw, m.domain, b);
  if (m.kind != mesh::ModelKind::kTunnel) return;
  const mesh::Outline opening = mesh::tunnel_outline(m.tunnel);
  const double tol = collar_tolerance(m), lining = m.tunnel.lining_thickness;
  const double inner = -(lining + tol);  // the lining's inner face, less the tolerance
  const bool ends_inside = depth(opening, s[2], s[3]) < inner;
  const double t = ends_inside ? 1.0 : deepest_along(opening, s);
  const double x = s[0] + t * (s[2] - s[0]), y = s[1] + t * (s[3] - s[1]);
  const double collar = depth(opening, s[0], s[1]);
  // Deepest at its collar, the bolt is misplaced at its start (below).
  if (depth(opening, x, y) < inner && depth(opening, x, y) < collar - tol)
    refuse(
        raw, b, ends_inside,
        std::string(ends_inside ? "lies in the opening: its end " : "runs through the opening: ") +
            "at " + point_text(x, y) + " is " + metres(-depth(opening, x, y)) +
            " inside the excavation boundary" +
            (lining > 0 ? " (the lining is " + metres(lining) + " thick)" : std::string()) +
            "; allowed: a bolt from the opening's boundary into the rock");
  if (collar > tol || collar < inner) {
    const bool reversed = collar > tol && std::abs(depth(opening, s[2], s[3])) <= tol;
    refuse(raw, b, false,
           "starts at " + point_text(s[0], s[1]) + ", " + metres(std::abs(collar)) +
               (collar > 0 ? " outside" : " inside") +
               " the excavation boundary; allowed: a collar (start) on the boundary" +
               (lining > 0 ? " or in the lining (" + metres(lining) + " thick)" : std::string()) +
               ", within " + metres(tol) + " (mesh.size_near / 2, at least 5 cm)" +
               (reversed ? "; its end is on the boundary: swap start and end" : ""));
  }
}

std::vector<std::string> unit_warnings(const RawScene& raw) {
  std::vector<std::string> out;
  for (const KeySpec& k : scene_schema()) {
    if (k.unit != "Pa" || k.path.find("[]") != std::string::npos) continue;
    const std::string name = k.path.substr(k.path.rfind('.') + 1);
    const bool stress = k.path.rfind("insitu.sigma_", 0) == 0;
    const bool modulus = name == "young" || name == "tangent_modulus";
    const double floor = stress ? 1e4 : 1e6;
    const toml::node* n = raw.root.at_path(k.path).node();
    if ((!stress && !modulus) || !n || !n->is_number()) continue;
    const double v = n->value<double>().value_or(0);
    if (v == 0 || std::abs(v) >= floor) continue;
    char problem[200];
    std::snprintf(problem, sizeof problem,
                  "%s of %g Pa is below %s: probably MPa given as Pa (%g MPa is %ge6)",
                  stress ? "an in-situ stress" : "a modulus", v, stress ? "10 kPa" : "1 MPa", v, v);
    out.push_back(key_message(raw, k.path, n, problem));
  }
  return out;
}

std::vector<std::string> damping_warnings(const RawScene& raw, const Scene& s) {
  std::string stages;
  for (const StageSpec& st : s.stages)
    if (st.kind != "load_platens") stages += (stages.empty() ? "" : ", ") + st.kind;
  const fdem::DampingSettings d = stage_damping(s);
  const bool contact_damped = s.engine.contact && s.engine.contact_damping > 0;
  if (stages.empty() || d.local > 0 || d.kinetic || d.mass_proportional > 0 ||
      s.engine.damping_ratio > 0 || contact_damped)
    return {};
  const std::string key = "engine.local_damping";
  return {key_message(raw, key, raw.root.at_path(key).node(),
                      "with no kinetic, mass, element (engine.damping_ratio) or contact damping "
                      "the quasi-static stages (" +
                          stages +
                          ") run undamped: their vibration never decays, blocks held by "
                          "friction ratchet down on it and equilibrium may not come; give "
                          "engine.local_damping > 0 (0.8 when not given) or "
                          "engine.kinetic_damping = true")};
}

}  // namespace rockfdem::workflows::detail
