#include "outputs/instruments.hpp"

#include <cmath>

#include "rockfdem/error.hpp"
#include "scene/scene_reader.hpp"

namespace rockfdem::workflows {
namespace {

double mm(double metres) { return 1000 * metres; }

std::string num(double v) { return detail::number_text(v); }

// The point's triangle, refused where a reading means nothing: outside
// every triangle, or in the core the excavation takes away.
MaterialPoint place(const Scene& scene, const mesh::Mesh& m, const fdem::Engine& e,
                    const std::string& what, double x, double y) {
  const std::optional<MaterialPoint> p = locate(m, e, x, y);
  const std::string at = scene.source + ": " + what + " at (" + num(x) + ", " + num(y) + ") m ";
  if (!p)
    throw InputError(at +
                     "lies in no triangle of the mesh (outside the rock domain or in a hole); "
                     "allowed: a point in the rock or the lining");
  if (p->zone == mesh::kCore)
    throw InputError(at + "lies in the excavated core (triangle " + std::to_string(p->triangle) +
                     "); allowed: a point in the rock or the lining");
  return *p;
}

const Monitor& key_point(const std::vector<Monitor>& key_points, const std::string& name) {
  for (const Monitor& k : key_points)
    if (k.name == name) return k;
  throw std::logic_error("no key point " + name);
}

}  // namespace

Instruments::Instruments(const Scene& scene, const mesh::Mesh& m, const fdem::Engine& e,
                         const std::vector<Monitor>& key_points, const fdem::BoltPlan& bolts)
    : specs_(scene.monitors),
      half_width_(fracture_resolution(scene, &m).h / 2),
      bolted_(bolt_triangles(&bolts, m.n_triangles())) {
  for (std::size_t i = 0; i < scene.monitors.size(); ++i) {
    const MonitorSpec& s = scene.monitors[i];
    monitors_.push_back(
        place(scene, m, e, "monitor[" + std::to_string(i) + "] \"" + s.name + "\"", s.x, s.y));
  }
  for (std::size_t i = 0; i < scene.extensometers.size(); ++i) {
    const ExtensometerSpec& s = scene.extensometers[i];
    Extensometer x{&s, s.head_x, s.head_y, s.dir_x, s.dir_y, {}};
    if (!s.from.empty()) {
      const Monitor& k = key_point(key_points, s.from);
      x.x = k.x, x.y = k.y, x.dx = -k.inward_x, x.dy = -k.inward_y;
    }
    const std::string key = "extensometer[" + std::to_string(i) + "] \"" + s.name + "\" ";
    for (int a = 0; a <= s.anchors; ++a) {
      const double depth = s.length * a / s.anchors;
      x.points.push_back(place(scene, m, e, key + (a ? "anchor " + std::to_string(a) : "head"),
                               x.x + depth * x.dx, x.y + depth * x.dy));
    }
    extensometers_.push_back(std::move(x));
  }
  for (const Monitor& k : key_points) {
    ray_names_.push_back(k.name);
    rays_.push_back({k.x, k.y, -k.inward_x, -k.inward_y});
  }
}

std::vector<std::string> Instruments::history_columns() const {
  std::vector<std::string> cols;
  for (const MonitorSpec& s : specs_)
    for (const char* c : {"_ux_mm", "_uy_mm", "_u_mm"}) cols.push_back(s.name + c);
  for (const Extensometer& x : extensometers_) {
    const int n = x.spec->anchors;
    for (int a = 0; a < n; ++a) cols.push_back(x.spec->name + "_a" + std::to_string(a) + "_mm");
    for (int a = 0; a <= n; ++a)
      cols.push_back(x.spec->name + "_a" + std::to_string(a) + "_abs_mm");
  }
  for (const std::string& k : ray_names_) cols.push_back(k + "_broken_depth_m");
  return cols;
}

std::array<double, 2> Instruments::monitor_u(std::size_t i, const NodeDisplacement& u) const {
  const std::array<double, 2> d = interpolate(monitors_[i], u);
  if (!specs_[i].relative_to_support) return d;
  if (!installed_) return {0, 0};
  return {d[0] - support_u_[2 * i], d[1] - support_u_[2 * i + 1]};
}

std::vector<double> Instruments::axial(const Extensometer& x, const NodeDisplacement& u) const {
  std::vector<double> out;
  for (const MaterialPoint& p : x.points) {
    const std::array<double, 2> d = interpolate(p, u);
    out.push_back(-(d[0] * x.dx + d[1] * x.dy));
  }
  return out;
}

std::vector<double> Instruments::reading(std::size_t i, const NodeDisplacement& u) const {
  const Extensometer& x = extensometers_[i];
  std::vector<double> a = axial(x, u);
  if (!x.spec->relative_to_support) return a;
  std::size_t at = 0;  // x's first point in support_axial_
  for (std::size_t k = 0; k < i; ++k) at += extensometers_[k].points.size();
  for (std::size_t k = 0; k < a.size(); ++k) a[k] = installed_ ? a[k] - support_axial_[at + k] : 0;
  return a;
}

void Instruments::support_installed(const NodeDisplacement& u) {
  if (installed_) return;
  installed_ = true;
  support_u_.clear();
  for (const MaterialPoint& p : monitors_)
    for (double v : interpolate(p, u)) support_u_.push_back(v);
  support_axial_.clear();
  for (const Extensometer& x : extensometers_)
    for (double v : axial(x, u)) support_axial_.push_back(v);
}

std::vector<double> Instruments::row(const fdem::Engine& e, const mesh::Mesh& m,
                                     const NodeDisplacement& u) const {
  std::vector<double> row;
  for (std::size_t i = 0; i < monitors_.size(); ++i) {
    const std::array<double, 2> d = monitor_u(i, u);
    row.insert(row.end(), {mm(d[0]), mm(d[1]), mm(std::hypot(d[0], d[1]))});
  }
  for (std::size_t i = 0; i < extensometers_.size(); ++i) {
    const std::vector<double> a = reading(i, u);
    for (std::size_t k = 0; k + 1 < a.size(); ++k) row.push_back(mm(a[k] - a.back()));
    for (double v : a) row.push_back(mm(v));
  }
  for (double d : broken_depth_along_rays(e, m, rays_, half_width_, bolted_)) row.push_back(d);
  return row;
}

void Instruments::add_monitors(MonitorRecord& monitors, const NodeDisplacement& u) const {
  for (std::size_t i = 0; i < monitors_.size(); ++i) {
    const MonitorSpec& s = specs_[i];
    const std::array<double, 2> d = monitor_u(i, u);
    monitors.points[s.name] = {mm(d[0]),
                               mm(d[1]),
                               mm(std::hypot(d[0], d[1])),
                               s.x,
                               s.y,
                               long(monitors_[i].triangle),
                               s.relative_to_support ? "support" : "in-situ state"};
  }
}

void Instruments::finish(RunRecord& summary, const fdem::Engine& e, const mesh::Mesh& m,
                         const NodeDisplacement& u) const {
  for (std::size_t i = 0; i < extensometers_.size(); ++i) {
    const Extensometer& x = extensometers_[i];
    const std::vector<double> a = reading(i, u);
    ExtensometerFigures& f = summary.extensometers[x.spec->name];
    f = ExtensometerFigures{{x.x, x.y}, {x.dx, x.dy}, std::nullopt, x.spec->length, {}};
    f.read_from = x.spec->relative_to_support ? "support" : "in-situ state";
    if (!x.spec->from.empty()) f.from = x.spec->from;
    for (std::size_t k = 0; k < a.size(); ++k)
      f.points.push_back({k == 0 ? "head" : "anchor " + std::to_string(k),
                          x.spec->length * double(k) / x.spec->anchors, mm(a[k] - a.back()),
                          mm(a[k])});
  }
  BrokenZoneRecord& zone =
      summary.broken_zone ? *summary.broken_zone : summary.broken_zone.emplace();
  const std::vector<double> depth = broken_depth_along_rays(e, m, rays_, half_width_, bolted_);
  std::vector<double> damaged;
  if (!grouted_.empty())
    damaged = broken_depth_along_rays(e, m, rays_, half_width_, bolted_, grouted_);
  for (std::size_t i = 0; i < rays_.size(); ++i) {
    RayFigures& r = zone.rays[ray_names_[i]];
    r = {depth[i], std::nullopt, {rays_[i].x, rays_[i].y}, {rays_[i].dx, rays_[i].dy}};
    if (!damaged.empty()) r.damaged_depth_m = damaged[i];
  }
  zone.ray_half_width_m = half_width_;
}

void Instruments::cracks_grouted(const std::vector<StageChanges::Grouted>& grouted,
                                 std::size_t n_cracks) {
  grouted_.resize(n_cracks, 0);
  for (const StageChanges::Grouted& g : grouted) grouted_.at(g.crack) = 1;
}

nlohmann::json Instruments::state() const {
  std::vector<std::size_t> grouted;
  for (std::size_t c = 0; c < grouted_.size(); ++c)
    if (grouted_[c]) grouted.push_back(c);
  return {{"support_installed", installed_},
          {"support_u", support_u_},
          {"support_axial", support_axial_},
          {"grouted_cracks", grouted},
          {"cracks", grouted_.size()}};
}

void Instruments::restore(const nlohmann::json& s) {
  installed_ = s.value("support_installed", false);
  support_u_ = s.value("support_u", std::vector<double>{});
  support_axial_ = s.value("support_axial", std::vector<double>{});
  grouted_.assign(s.value("cracks", std::size_t{0}), 0);
  for (std::size_t c : s.value("grouted_cracks", std::vector<std::size_t>{})) {
    if (c >= grouted_.size())
      throw InputError("corrupt run state: the instruments' grouted crack " + std::to_string(c) +
                       " is beyond the " + std::to_string(grouted_.size()) + " crack elements");
    grouted_[c] = 1;
  }
  // Only a relative extensometer reads it (a state of an earlier version has none).
  std::size_t points = 0;
  bool relative = false;
  for (const Extensometer& x : extensometers_) {
    points += x.points.size();
    relative = relative || x.spec->relative_to_support;
  }
  if (installed_ && relative && support_axial_.size() != points)
    throw InputError(
        "corrupt run state: the instruments' support reference holds " +
        std::to_string(support_axial_.size()) + " extensometer readings; the scene's " +
        std::to_string(extensometers_.size()) + " extensometers need " + std::to_string(points));
  if (installed_ && support_u_.size() != 2 * monitors_.size())
    throw InputError("corrupt run state: the instruments' support reference holds " +
                     std::to_string(support_u_.size()) + " values; the scene's " +
                     std::to_string(monitors_.size()) + " monitors need " +
                     std::to_string(2 * monitors_.size()));
}

}  // namespace rockfdem::workflows
