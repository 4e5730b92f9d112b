#include "outputs/support_diagrams.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "outputs/broken_zone.hpp"
#include "rockfdem/fdem/bolt_sections.hpp"
#include "rockfdem/mesh/outline.hpp"

namespace rockfdem::workflows {
namespace {

// The diagrams' colours: compression blue, tension red (the lining's
// thrust and the bolts' force alike), the moment dark green.
constexpr std::array<double, 3> kCompression{0.1, 0.25, 0.85};
constexpr std::array<double, 3> kTension{0.85, 0.05, 0.05};
constexpr std::array<double, 3> kMoment{0.0, 0.5, 0.15};

// Each diagram's largest ordinate, as a share of the opening's width: the
// ring's N and M inside the opening, the bolts' beside bars about a metre
// apart.
constexpr double kThrustLength = 0.12, kMomentLength = 0.08, kBoltLength = 0.06;

std::string number(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%g", v);
  return s;
}

double max_abs(const std::vector<DiagramPoint>& p) {
  double m = 0;
  for (const DiagramPoint& d : p) m = std::max(m, std::abs(d.value));
  return m;
}

// Where the diagram draws point p's ordinate.
std::array<double, 2> ordinate(const DiagramPoint& p, double scale) {
  return {p.x + p.nx * p.value / scale, p.y + p.ny * p.value / scale};
}

// A ring's segments join up (the last next to the first, as close as
// neighbours are): its diagram closes.
bool closed_ring(const LiningGeometry& g) {
  const auto& s = g.segments;
  if (s.size() < 3) return false;
  double spacing = 0;
  for (std::size_t i = 1; i < s.size(); ++i)
    spacing = std::max(spacing, std::hypot(s[i].x - s[i - 1].x, s[i].y - s[i - 1].y));
  return std::hypot(s.front().x - s.back().x, s.front().y - s.back().y) <= 1.5 * spacing;
}

// The member's own line (the ring's mid-line, a bolt's axis through its
// stations), thin dark grey and out of the legend.
void add_baseline(const std::vector<DiagramPoint>& p, bool closed, plots::PictureLines& line) {
  for (std::size_t i = 0; i + 1 < p.size(); ++i)
    line.segments.push_back({p[i].x, p[i].y, p[i + 1].x, p[i + 1].y});
  if (closed && p.size() > 2)
    line.segments.push_back({p.back().x, p.back().y, p.front().x, p.front().y});
}

// A mark labelled `what` at the ordinate of the largest |value| of `p`;
// returns that value's words ("N 2201 kN/m") for the notes, where
// neighbouring extremes' numbers cannot run into each other.
std::string label_extreme(const std::vector<DiagramPoint>& p, double scale, const std::string& what,
                          const std::string& unit, plots::MeshOverlay& labels) {
  if (p.empty()) return {};
  const auto at = std::max_element(p.begin(), p.end(), [](const auto& a, const auto& b) {
    return std::abs(a.value) < std::abs(b.value);
  });
  if (!(std::abs(at->value) > 0)) return {};
  const auto o = ordinate(*at, scale);
  labels.markers.push_back({o[0], o[1], what});
  char text[96];
  std::snprintf(text, sizeof text, "%s %.0f %s", what.c_str(), at->value, unit.c_str());
  return text;
}

// `head` and `items` joined by "; " into lines of at most kNoteWidth
// characters where the items allow (an item is never split): the notes
// box ends where the scale bar begins.
constexpr std::size_t kNoteWidth = 90;
std::vector<std::string> wrapped(const std::string& head, const std::vector<std::string>& items) {
  std::vector<std::string> lines;
  std::string line = head;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string piece = items[i] + (i + 1 < items.size() ? ";" : "");
    if (line.size() > head.size() && line.size() + 1 + piece.size() > kNoteWidth) {
      lines.push_back(line);
      line = "  ";
    }
    line += (line.size() > 2 && line != head ? " " : "") + piece;
  }
  if (!items.empty()) lines.push_back(line);
  return lines;
}

// The ring's runs (between its corners) grouped into the parts an
// engineer scales apart: a horseshoe's floor part (its runs' mean height
// below the inner walls' feet) carries many times the arch's thrust and
// would flatten it at one scale. One part, "ring", without a floor part.
struct RingPartRuns {
  std::string name;
  std::vector<std::vector<DiagramPoint>> n, m;
  std::vector<DiagramPoint> all_n, all_m;
};

std::vector<RingPartRuns> ring_part_runs(const Scene& scene,
                                         const std::vector<std::vector<DiagramPoint>>& n,
                                         const std::vector<std::vector<DiagramPoint>>& m) {
  const double top = scene.mesh.kind == mesh::ModelKind::kTunnel
                         ? mesh::invert_part_top(scene.mesh.tunnel)
                         : -INFINITY;
  std::vector<RingPartRuns> parts{{"arch and walls", {}, {}, {}, {}}, {"invert", {}, {}, {}, {}}};
  for (std::size_t r = 0; r < n.size() && r < m.size(); ++r) {
    double y = 0;
    for (const DiagramPoint& p : n[r]) y += p.y / double(n[r].size());
    RingPartRuns& part = parts[y < top];
    part.n.push_back(n[r]);
    part.m.push_back(m[r]);
    part.all_n.insert(part.all_n.end(), n[r].begin(), n[r].end());
    part.all_m.insert(part.all_m.end(), m[r].begin(), m[r].end());
  }
  if (parts[1].n.empty()) parts.pop_back();
  if (parts[0].n.empty()) parts.erase(parts.begin());
  if (parts.size() == 1) parts[0].name = "ring";
  return parts;
}

// The lines of the ring's diagrams, each part at its own scales (an item
// of `scales` per part), its extremes marked and worded (an item of
// `extremes` per part).
void ring_diagrams(const Scene& scene, const LiningGeometry& ring,
                   const std::vector<SectionForces>& forces, double span, plots::PictureLines& base,
                   std::vector<plots::PictureLines>& diagrams, std::vector<std::string>& scales,
                   std::vector<std::string>& extremes, plots::MeshOverlay& labels) {
  const bool corners = std::any_of(ring.segments.begin(), ring.segments.end(),
                                   [](const LiningSegment& s) { return s.corner; });
  const bool closed = !corners && closed_ring(ring);
  plots::PictureLines comp{"ring N, compression", kCompression, 2, {}};
  plots::PictureLines tens{"ring N, tension", kTension, 2, {}};
  plots::PictureLines mom{"ring M, tension side", kMoment, 2, {}};
  const std::vector<RingPartRuns> parts = ring_part_runs(scene, lining_diagram(ring, forces, false),
                                                         lining_diagram(ring, forces, true));
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const RingPartRuns& p = parts[i];
    const double sn = diagram_scale(max_abs(p.all_n), kThrustLength * span);
    const double sm = diagram_scale(max_abs(p.all_m), kMomentLength * span);
    for (const auto& run : p.n) {
      diagram_lines(run, sn, closed, comp, tens);
      add_baseline(run, closed, base);
    }
    for (const auto& run : p.m) diagram_lines(run, sm, closed, mom, mom);
    const std::string what = parts.size() > 1 ? p.name + " " : "";
    scales.push_back(what + "N " + number(sn) + " kN/m, M " + number(sm) + " kNm/m");
    std::string words;
    for (const std::string& e : {label_extreme(p.all_n, sn, "N", "kN/m", labels),
                                 label_extreme(p.all_m, sm, "M", "kNm/m", labels)})
      if (!e.empty()) words += (words.empty() ? what : ", ") + e;
    if (!words.empty()) extremes.push_back(words);
  }
  for (plots::PictureLines* l : {&comp, &tens, &mom})
    if (!l->segments.empty()) diagrams.push_back(*l);
  if (parts.size() > 1)
    labels.notes.push_back("The ring's parts are drawn at their own scales (above)");
  if (corners)
    labels.notes.push_back("The ring's corner segments (no beam section there) are not drawn");
}

}  // namespace

double diagram_scale(double max_abs_value, double length) {
  if (!(max_abs_value > 0) || !(length > 0)) return 1;
  const double s = max_abs_value / length;  // per metre drawn, to be rounded up
  const double p = std::pow(10.0, std::floor(std::log10(s)));
  const double f = s / p;
  return (f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10) * p;
}

void diagram_lines(const std::vector<DiagramPoint>& p, double scale, bool closed,
                   plots::PictureLines& positive, plots::PictureLines& negative) {
  const auto set = [&](double v) -> plots::PictureLines& { return v >= 0 ? positive : negative; };
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto o = ordinate(p[i], scale);
    set(p[i].value).segments.push_back({p[i].x, p[i].y, o[0], o[1]});
    if (i + 1 == p.size() && !(closed && p.size() > 2)) break;
    const DiagramPoint& q = p[(i + 1) % p.size()];
    const auto oq = ordinate(q, scale);
    set(0.5 * (p[i].value + q.value)).segments.push_back({o[0], o[1], oq[0], oq[1]});
  }
}

std::vector<std::vector<DiagramPoint>> lining_diagram(const LiningGeometry& g,
                                                      const std::vector<SectionForces>& f,
                                                      bool moment) {
  std::vector<std::vector<DiagramPoint>> runs(1);
  for (std::size_t i = 0; i < g.segments.size() && i < f.size(); ++i) {
    const LiningSegment& s = g.segments[i];
    if (s.corner) {  // no beam section: the run ends here
      if (!runs.back().empty()) runs.emplace_back();
      continue;
    }
    runs.back().push_back({s.x, s.y, -s.nx, -s.ny, (moment ? f[i].moment : f[i].thrust) / 1e3});
  }
  if (runs.back().empty()) runs.pop_back();
  // A run through segment 0 continues the last one (the ring is a loop).
  if (runs.size() > 1 && !g.segments.front().corner && !g.segments.back().corner) {
    runs.back().insert(runs.back().end(), runs.front().begin(), runs.front().end());
    runs.erase(runs.begin());
  }
  return runs;
}

std::vector<DiagramPoint> bolt_diagram(const PictureContext& c, std::size_t b) {
  const auto& axis = c.scene.bolts.segments[b];
  const double ax = axis[2] - axis[0], ay = axis[3] - axis[1], length = std::hypot(ax, ay);
  std::vector<DiagramPoint> out;
  if (!(length > 0)) return out;
  // On the bar's axis as built at each station's distance from the head
  // (the stations' centroids wander about it by up to half a triangle).
  const double dx = ax / length, dy = ay / length;
  for (const fdem::BoltStation& s : fdem::bolt_sections(c.e, *c.bolts, int(b)))
    out.push_back({axis[0] + s.station * dx, axis[1] + s.station * dy, -dy, dx, s.bar_force / 1e3});
  return out;
}

plots::MeshPicture support_forces_picture(const PictureContext& c, const LiningGeometry* ring,
                                          const std::vector<SectionForces>* forces,
                                          plots::MeshOverlay& labels) {
  plots::MeshPicture p;
  p.title = "Support forces, end of run: lining thrust N and moment M, bolt axial force";
  p.bar_title = "model";
  p.view = opening_window(c.m);
  const double width = p.view ? p.view->x1 - p.view->x0 : 10.0;
  const double span = width / 3;  // the window is the opening and a span on each side
  // The model in light colours, the opening white.
  const std::vector<char> bolted = bolt_triangles(c.bolts, c.m.n_triangles());
  p.hidden.resize(c.e.n_triangles());
  bool lining_shown = false, bolts_shown = false;
  for (std::size_t t = 0; t < c.e.n_triangles(); ++t) {
    p.hidden[t] = !c.e.active(t);
    const bool bolt = !bolted.empty() && bolted[t];
    const bool lining = c.m.zone[t] == mesh::kLining;
    p.values.push_back(bolt ? 2 : lining ? 1 : 0);
    lining_shown |= lining && !p.hidden[t];
    bolts_shown |= bolt && !p.hidden[t];
  }
  p.categories = {{0, "rock"}};
  if (lining_shown) p.categories.push_back({1, "lining"});
  if (bolts_shown) p.categories.push_back({2, "bolt, grout"});
  plots::PictureLines base{"", {0.3, 0.3, 0.3}, 1, {}};
  std::vector<plots::PictureLines> diagrams;
  std::vector<std::string> scales, extremes;
  if (ring && forces && !forces->empty())
    ring_diagrams(c.scene, *ring, *forces, span, base, diagrams, scales, extremes, labels);
  if (c.bolts) {
    std::vector<std::vector<DiagramPoint>> bars;
    double largest = 0;
    for (std::size_t b = 0; b < c.scene.bolts.segments.size(); ++b) {
      if (b >= c.bolts->installed.size() || !c.bolts->installed[b]) continue;
      bars.push_back(bolt_diagram(c, b));
      largest = std::max(largest, max_abs(bars.back()));
    }
    const double sb = diagram_scale(largest, kBoltLength * span);
    plots::PictureLines tens{"bolt N, tension", kTension, 2, {}};
    plots::PictureLines comp{"bolt N, compression", kCompression, 2, {}};
    const DiagramPoint* peak = nullptr;
    for (const std::vector<DiagramPoint>& bar : bars) {
      diagram_lines(bar, sb, false, tens, comp);
      add_baseline(bar, false, base);
      for (const DiagramPoint& d : bar)
        if (!peak || std::abs(d.value) > std::abs(peak->value)) peak = &d;
    }
    for (plots::PictureLines* l : {&tens, &comp})
      if (!l->segments.empty()) diagrams.push_back(*l);
    if (peak) extremes.push_back(label_extreme({*peak}, sb, "bolt", "kN per bar", labels));
    if (!bars.empty()) scales.push_back("bolts " + number(sb) + " kN per bar");
  }
  std::vector<std::string> head = wrapped("Diagram scales, 1 m drawn: ", scales);
  for (const std::string& line : wrapped("Largest (marked): ", extremes)) head.push_back(line);
  labels.notes.insert(labels.notes.begin(), head.begin(), head.end());
  p.lines.push_back(std::move(base));
  for (plots::PictureLines& l : diagrams) p.lines.push_back(std::move(l));
  p.overlay = &labels;
  return p;
}

void support_forces_plot(PlotWriter& plots, const PictureContext& c, const LiningGeometry* ring,
                         const std::vector<SectionForces>* forces) {
  const bool any_bolt = c.bolts && std::any_of(c.bolts->installed.begin(), c.bolts->installed.end(),
                                               [](auto installed) { return bool(installed); });
  if (!any_bolt && !(ring && forces && !forces->empty())) return;
  plots::MeshOverlay labels;
  plots.picture("support_forces.png", picture_grid(c.e),
                support_forces_picture(c, ring, forces, labels));
}

}  // namespace rockfdem::workflows
