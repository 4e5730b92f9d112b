// Each meshed trace's joint elements by state, for joints.csv and the summary.
#include "outputs/joint_results.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/coupling/joint_cracks.hpp"

namespace rockfdem::workflows {

JointRecord joint_results(const fdem::Engine& e, const mesh::Mesh& m,
                          const std::vector<mesh::JointTrace>& traces,
                          const std::string& csv_path) {
  const std::vector<std::int32_t> on = coupling::joint_crack_traces(e, m);
  const coupling::JointCounts n = coupling::count_joint_cracks(e, on);
  JointRecord r;
  r.elements = n.elements;
  r.active = n.active;
  r.yielding = n.yielding;
  r.residual = n.residual;
  // Per trace: the same counts over its own elements.
  std::vector<coupling::JointCounts> per(traces.size());
  for (std::size_t k = 0; k < traces.size(); ++k) {
    std::vector<std::int32_t> only(on.size(), 0);
    for (std::size_t c = 0; c < on.size(); ++c) only[c] = on[c] == std::int32_t(k + 1);
    per[k] = coupling::count_joint_cracks(e, only);
  }
  std::string csv = "trace,x0_m,y0_m,x1_m,y1_m,length_m,elements,active,yielding,residual\n";
  char row[256];
  for (std::size_t k = 0; k < traces.size(); ++k) {
    const mesh::JointTrace& t = traces[k];
    std::snprintf(row, sizeof row, "%zu,%.6f,%.6f,%.6f,%.6f,%.6f,%ld,%ld,%ld,%ld\n", k + 1, t.x0,
                  t.y0, t.x1, t.y1, mesh::trace_length(t), per[k].elements, per[k].active,
                  per[k].yielding, per[k].residual);
    csv += row;
  }
  coupling::atomic_write_text(csv_path, csv);
  return r;
}

namespace {

/// A joint element's row: where it sits along its trace and how it stands.
struct ProfileRow {
  int trace = 0;  ///< 1-based
  double distance = 0, x = 0, y = 0;
  std::size_t element = 0;
};

/// The state word of joint element c: inactive (a triangle removed), open
/// (its faces apart at the midpoint beyond the law's zero: no normal
/// stress from contact), sliding (at the residual friction, damage 1),
/// yielding (past the peak) or intact.
const char* joint_state(const fdem::Engine& e, std::size_t c, const fdem::CrackDisplacement& u) {
  const auto tri = e.crack_triangles(c);
  if (!e.active(tri[0]) || !e.active(tri[1])) return "inactive";
  if (u.law_opening[1] > 0.0) return "open";
  const double d = e.crack_damage(c);
  if (d >= 1.0) return "sliding";
  return d > 0.0 ? "yielding" : "intact";
}

}  // namespace

std::string joint_profile_csv(const fdem::Engine& e, const mesh::Mesh& m,
                              const std::vector<mesh::JointTrace>& traces) {
  const std::vector<std::int32_t> on = coupling::joint_crack_traces(e, m);
  const std::vector<int>& vertex = e.node_vertex();
  std::vector<ProfileRow> rows;
  for (std::size_t c = 0; c < on.size(); ++c) {
    const int k = on[c];
    if (k <= 0 || std::size_t(k) > traces.size()) continue;
    const mesh::JointTrace& t = traces[k - 1];
    const auto nodes = e.crack_nodes(c);
    const int a = vertex[nodes[0]], b = vertex[nodes[1]];
    ProfileRow r;
    r.trace = k;
    r.element = c;
    r.x = 0.5 * (m.x[a] + m.x[b]);
    r.y = 0.5 * (m.y[a] + m.y[b]);
    const double len = mesh::trace_length(t);
    r.distance = len > 0 ? ((r.x - t.x0) * (t.x1 - t.x0) + (r.y - t.y0) * (t.y1 - t.y0)) / len : 0;
    rows.push_back(r);
  }
  std::sort(rows.begin(), rows.end(), [](const ProfileRow& p, const ProfileRow& q) {
    return std::tie(p.trace, p.distance, p.element) < std::tie(q.trace, q.distance, q.element);
  });
  std::string csv =
      "trace,element,distance_m,x_m,y_m,length_m,slip_mm,opening_mm,aperture_mm,"
      "max_slip_mm,damage,state\n";
  char line[320];
  for (const ProfileRow& r : rows) {
    const fdem::CrackDisplacement u = e.crack_displacement(r.element);
    // Simpson means over the element (the midpoint's values are the ends'
    // means, so the mean is the ends' mean).
    const double slip = (u.slip[0] + 4 * u.slip[1] + u.slip[2]) / 6;
    const double opening = (u.opening[0] + 4 * u.opening[1] + u.opening[2]) / 6;
    const double law_opening = (u.law_opening[0] + 4 * u.law_opening[1] + u.law_opening[2]) / 6;
    const double max_slip = std::max({std::fabs(u.slip[0]), std::fabs(u.slip[2])});
    std::snprintf(line, sizeof line, "%d,%zu,%.6f,%.6f,%.6f,%.6f,%.6g,%.6g,%.6g,%.6g,%.6g,%s\n",
                  r.trace, r.element, r.distance, r.x, r.y, u.length, 1e3 * slip, 1e3 * opening,
                  1e3 * std::max(law_opening, 0.0), 1e3 * max_slip, e.crack_damage(r.element),
                  joint_state(e, r.element, u));
    csv += line;
  }
  return csv;
}

}  // namespace rockfdem::workflows
