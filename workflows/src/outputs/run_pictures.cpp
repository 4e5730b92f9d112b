#include "outputs/run_pictures.hpp"

#include <cmath>
#include <map>
#include <set>

#include "outputs/broken_zone.hpp"
#include "outputs/picture_outlines.hpp"
#include "rockfdem/coupling/joint_cracks.hpp"
#include "rockfdem/fdem/bolt_sections.hpp"
#include "rockfdem/mesh/opening.hpp"

namespace rockfdem::workflows {
namespace {

using Segment = std::array<double, 4>;

Segment between(const fdem::Engine& e, int a, int b) {
  const std::vector<double>& p = e.positions();
  return {p[2 * a], p[2 * a + 1], p[2 * b], p[2 * b + 1]};
}

// Broken crack elements, by mode or all in black; those next to a
// triangle flagged in `skip` (bolt steel and grout, drawn as the bolts)
// are left out, as in the broken zone's figures.
std::vector<plots::PictureLines> broken_cracks(const fdem::Engine& e, const std::vector<char>& skip,
                                               bool by_mode) {
  std::vector<plots::PictureLines> sets{{"broken, mode I", {0.0, 0.0, 0.0}, 2, {}},
                                        {"broken, mode II", {0.0, 0.2, 1.0}, 2, {}},
                                        {"broken, mixed", {0.0, 0.6, 0.0}, 2, {}}};
  if (!by_mode) sets = {{"broken cracks", {0.0, 0.0, 0.0}, 2, {}}};
  for (std::size_t k = 0; k < e.n_cracks(); ++k) {
    if (e.crack_state(k) != fdem::CrackState::kBroken) continue;
    const auto t = e.crack_triangles(k);
    if (!skip.empty() && (skip[t[0]] || skip[t[1]])) continue;
    const fdem::FailureMode mode = e.crack_mode(k);
    const std::size_t set = !by_mode                             ? 0
                            : mode == fdem::FailureMode::kModeII ? 1
                            : mode == fdem::FailureMode::kMixed  ? 2
                                                                 : 0;
    const auto n = e.crack_nodes(k);
    sets[set].segments.push_back(between(e, n[0], n[1]));
  }
  return sets;
}

// Joint elements between two active triangles by state, told apart from
// the rock's cracks by their purple and cyan: intact, sliding (past the
// peak), opened by more than kOpenedJoint; one legend entry per state drawn.
constexpr double kOpenedJoint = 1e-3;  // [m]

std::vector<plots::PictureLines> joint_lines(const fdem::Engine& e, const mesh::Mesh& m) {
  if (m.joint_edges.empty()) return {};
  const std::vector<std::int32_t> on = coupling::joint_crack_traces(e, m);
  std::vector<plots::PictureLines> sets{{"joint, intact", {0.62, 0.52, 0.82}, 1.5, {}},
                                        {"joint, sliding", {0.45, 0.0, 0.7}, 2.5, {}},
                                        {"joint, opened > 1 mm", {0.0, 0.75, 0.85}, 3, {}}};
  for (std::size_t k = 0; k < e.n_cracks(); ++k) {
    if (!on[k]) continue;
    const auto t = e.crack_triangles(k);
    if (!e.active(t[0]) || !e.active(t[1])) continue;
    const auto n = e.crack_nodes(k);
    sets[std::size_t(coupling::joint_state(e, k, kOpenedJoint))].segments.push_back(
        between(e, n[0], n[1]));
  }
  std::vector<plots::PictureLines> out;
  for (auto& l : sets)
    if (!l.segments.empty()) out.push_back(std::move(l));
  return out;
}

// The installed lining's faces: edges of one active lining triangle only.
plots::PictureLines lining_faces(const PictureContext& c) {
  std::map<std::pair<int, int>, std::pair<int, Segment>> edges;  // mesh vertices -> count, segment
  for (std::size_t t = 0; t < c.m.n_triangles(); ++t) {
    if (c.m.zone[t] != mesh::kLining || !c.e.active(t)) continue;
    const auto v = c.m.triangles[t];
    const auto n = c.e.triangle_nodes(t);
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      auto& edge = edges[std::minmax(v[i], v[j])];
      ++edge.first;
      edge.second = between(c.e, n[i], n[j]);
    }
  }
  plots::PictureLines faces{"shotcrete lining", {0.35, 0.2, 0.05}, 2, {}};
  for (const auto& [key, edge] : edges)
    if (edge.first == 1) faces.segments.push_back(edge.second);
  return faces;
}

// Bolts and cables drawn through their stations (fdem::bolt_sections),
// each piece coloured by its station's axial force as a share of the bar's
// yield force fy pi d^2 / 4: compression cyan, tension from pale to dark
// red, yielded or broken purple; one legend entry per class drawn.
std::vector<plots::PictureLines> bolt_lines(const PictureContext& c) {
  std::vector<plots::PictureLines> classes{{"bolt: compression", {0.0, 0.75, 0.75}, 4, {}},
                                           {"bolt: < 25% of yield", {1.0, 0.75, 0.6}, 4, {}},
                                           {"bolt: 25-50% of yield", {0.95, 0.5, 0.35}, 4, {}},
                                           {"bolt: 50-100% of yield", {0.8, 0.15, 0.1}, 4, {}},
                                           {"bolt: yielded, broken", {0.4, 0.0, 0.5}, 4, {}}};
  const BoltSettings& b = c.scene.bolts;
  for (std::size_t i = 0; i < b.segments.size(); ++i) {
    if (!c.bolts || i >= c.bolts->installed.size() || !c.bolts->installed[i]) continue;
    const SteelSettings& steel = b.is_cable[i] ? b.cable : b.bolt;
    const double yield = steel.yield_strength * 0.25 * M_PI * steel.diameter * steel.diameter;
    const std::vector<fdem::BoltStation> st = fdem::bolt_sections(c.e, *c.bolts, int(i));
    const Segment& axis = b.segments[i];
    for (std::size_t k = 0; k < st.size(); ++k) {
      // From halfway to the previous station (or the head) to halfway to the next (or the end).
      const double x0 = k == 0 ? axis[0] : 0.5 * (st[k - 1].x + st[k].x);
      const double y0 = k == 0 ? axis[1] : 0.5 * (st[k - 1].y + st[k].y);
      const double x1 = k + 1 == st.size() ? axis[2] : 0.5 * (st[k].x + st[k + 1].x);
      const double y1 = k + 1 == st.size() ? axis[3] : 0.5 * (st[k].y + st[k + 1].y);
      const double share = st[k].bar_force / yield;
      const std::size_t cls = st[k].state > 0 ? 4
                              : share < 0     ? 0
                              : share < 0.25  ? 1
                              : share < 0.5   ? 2
                                              : 3;
      classes[cls].segments.push_back({x0, y0, x1, y1});
    }
  }
  std::vector<plots::PictureLines> out;
  for (const auto& l : classes)
    if (!l.segments.empty()) out.push_back(l);
  return out;
}

// Excavated triangles are left out: the opening shows white.
std::vector<std::uint8_t> excavated(const fdem::Engine& e) {
  std::vector<std::uint8_t> hidden(e.n_triangles());
  for (std::size_t t = 0; t < hidden.size(); ++t) hidden[t] = !e.active(t);
  return hidden;
}

// The fracture zone's edge (dashes of a hundredth of the window's width)
// and, with a displacement, the opening's magnified deformed outline.
void add_outlines(const PictureContext& c, plots::MeshPicture& p) {
  const double width = p.view ? p.view->x1 - p.view->x0 : 0.0;
  plots::PictureLines edge = fracture_zone_lines(c.m, 0.01 * width);
  if (!edge.segments.empty()) p.lines.push_back(std::move(edge));
  if (!c.u) return;
  if (auto outline = deformed_opening(c.e, c.m, c.u)) p.lines.push_back(std::move(*outline));
}

// The zoomed picture's frame: the window, the lines, the opening left
// out. A stress picture (`stress`) leaves out the bolts' strip triangles
// too: steel stresses would set the rock's colour scale, and the bolts
// are drawn as lines over them.
plots::MeshPicture framed(const PictureContext& c, bool stress) {
  plots::MeshPicture p;
  p.hidden = excavated(c.e);
  const std::vector<char> bolted = bolt_triangles(c.bolts, c.m.n_triangles());
  if (stress)
    for (std::size_t t = 0; t < bolted.size(); ++t) p.hidden[t] |= bolted[t];
  p.lines = broken_cracks(c.e, bolted, !stress);
  if (!stress)
    for (auto& l : joint_lines(c.e, c.m)) p.lines.push_back(std::move(l));
  plots::PictureLines lining = lining_faces(c);
  if (!lining.segments.empty()) p.lines.push_back(lining);
  for (const auto& l : bolt_lines(c)) p.lines.push_back(l);
  p.view = opening_window(c.m);
  add_outlines(c, p);
  return p;
}

}  // namespace

coupling::VtkGrid picture_grid(const fdem::Engine& e) {
  coupling::VtkGrid g;
  const std::vector<double>& pos = e.positions();
  for (std::size_t i = 0; i < e.n_nodes(); ++i) {
    g.x.push_back(pos[2 * i]);
    g.y.push_back(pos[2 * i + 1]);
  }
  for (std::size_t t = 0; t < e.n_triangles(); ++t) g.triangles.push_back(e.triangle_nodes(t));
  return g;
}

std::optional<plots::MeshView> opening_window(const mesh::Mesh& m) {
  const std::optional<mesh::OpeningBoundary> b = mesh::find_opening(m);
  if (!b) return std::nullopt;
  const double span = b->xmax - b->xmin;
  return plots::MeshView{b->xmin - span, b->xmax + span, b->ymin - span, b->ymax + span};
}

plots::MeshPicture displacement_picture(const PictureContext& c) {
  plots::MeshPicture p = framed(c, false);
  p.title = "Displacement magnitude |u| from the in-situ state [mm], end of run";
  p.bar_title = "|u| [mm]";
  p.per_point = true;
  p.magnitude = true;
  for (std::size_t n = 0; n < c.e.n_nodes(); ++n) {
    const auto d = c.u ? c.u(int(n)) : std::array<double, 2>{0, 0};
    p.values.push_back(1000 * std::hypot(d[0], d[1]));
  }
  return p;
}

plots::MeshPicture principal_picture(const PictureContext& c, bool most_compressive) {
  plots::MeshPicture p = framed(c, true);
  p.title = std::string(most_compressive ? "Most" : "Least") +
            " compressive in-plane principal stress [MPa], end of run";
  p.bar_title =
      std::string(most_compressive ? "most" : "least") + " compressive [MPa]\ncompression +";
  for (std::size_t t = 0; t < c.e.n_triangles(); ++t)
    p.values.push_back(compressive_principal_mpa(c.e, t)[most_compressive ? 0 : 1]);
  return p;
}

plots::MeshPicture mesh_picture(const PictureContext& c) {
  plots::MeshPicture p;
  p.title = c.m.joint_edges.empty() ? "Final mesh: zones, broken cracks in red"
                                    : "Final mesh: zones, broken cracks in red, joints by state";
  p.bar_title = "zone";
  p.edges = true;
  p.hidden = excavated(c.e);
  const std::vector<char> bolted = bolt_triangles(c.bolts, c.m.n_triangles());
  std::set<int> present;
  for (std::size_t t = 0; t < c.e.n_triangles(); ++t) {
    const bool cracks = !c.m.fracture.empty() && c.m.fracture[t];
    p.values.push_back(!bolted.empty() && bolted[t]   ? 3
                       : c.m.zone[t] == mesh::kLining ? 2
                       : cracks                       ? 0
                                                      : 1);
    if (!p.hidden[t]) present.insert(int(p.values.back()));
  }
  const char* names[] = {"rock, cracks", "rock, no cracks", "lining", "bolt, grout"};
  for (const int code : present) p.categories.push_back({code, names[code]});
  p.lines = broken_cracks(c.e, {}, false);
  p.lines.front().rgb = {0.85, 0.0, 0.0};
  p.lines.front().width = 2.5;
  for (auto& l : joint_lines(c.e, c.m)) p.lines.push_back(std::move(l));
  p.view = opening_window(c.m);
  plots::PictureLines edge =
      fracture_zone_lines(c.m, p.view ? 0.01 * (p.view->x1 - p.view->x0) : 0);
  if (!edge.segments.empty()) p.lines.push_back(std::move(edge));
  return p;
}

plots::MeshPicture specimen_mesh_picture(const fdem::Engine& e) {
  plots::MeshPicture p;
  p.title = "Final mesh (as deformed): broken cracks in red";
  p.bar_title = "zone";
  p.edges = true;
  p.hidden = excavated(e);
  p.values.assign(e.n_triangles(), 0.0);
  p.categories = {{0, "rock"}};
  p.lines = broken_cracks(e, {}, false);
  p.lines.front().rgb = {0.85, 0.0, 0.0};
  p.lines.front().width = 2.5;
  return p;
}

plots::MeshPicture whole_model_picture(const fdem::Engine& e, bool most_tensile) {
  plots::MeshPicture p;
  p.title = std::string("Whole model: most ") + (most_tensile ? "tensile" : "compressive") +
            " in-plane principal stress [MPa], broken cracks in black";
  p.bar_title =
      most_tensile ? "most tensile [MPa]\ntension +" : "most compressive [MPa]\ncompression +";
  for (std::size_t t = 0; t < e.n_triangles(); ++t) {
    const auto s = compressive_principal_mpa(e, t);
    p.values.push_back(!e.active(t) ? std::nan("") : most_tensile ? -s[1] : s[0]);
  }
  p.lines = broken_cracks(e, {}, false);
  return p;
}

std::array<double, 2> compressive_principal_mpa(const fdem::Engine& e, std::size_t t) {
  // The engine's stress is tension positive; engineers read compression positive.
  const auto s = e.triangle_stress(t);
  const double centre = 0.5 * (s[0] + s[1]), radius = std::hypot(0.5 * (s[0] - s[1]), s[2]);
  return {1e-6 * (radius - centre), -1e-6 * (centre + radius)};
}

}  // namespace rockfdem::workflows
