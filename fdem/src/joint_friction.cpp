// Residual friction work of the joint elements (joint_friction.hpp).
#include "joint_friction.hpp"

#include <algorithm>
#include <cmath>

#include "crack_elements.hpp"
#include "energy.hpp"
#include "engine_data.hpp"
#include "parallel.hpp"
#include "rockfdem/fdem/crack_law.hpp"

namespace rockfdem::fdem::detail {
namespace {

bool is_joint(const EngineData& d, std::size_t c) {
  return d.crack_laws[d.cracks.material[c]].law == CrackLaw::kJoint;
}

/// The residual friction's nodal forces of joint element c now, on nodes 0
/// and 1 (nodes 3 and 2 take the opposite): f[0..1] and f[2..3]. The
/// crack loop's geometry and offsets, at its raised damage.
void residual_friction_force(const EngineData& d, std::size_t c, double f[4]) {
  for (int i = 0; i < 4; ++i) f[i] = 0.0;
  if (!d.cracks.active[c]) return;
  double os[6];
  const double h = law_openings(d, c, os);
  const double inv_h = 1.0 / h;
  const double o[3] = {os[0], os[2], os[4]}, s[3] = {os[1], os[3], os[5]};
  // The element's direction e = ((x1 + x2) - (x0 + x3)) / 2h.
  const int* nd = &d.cracks.nodes[4 * c];
  const double* p = d.nodes.pos.data();
  const double ex = 0.5 * ((p[2 * nd[1]] + p[2 * nd[2]]) - (p[2 * nd[0]] + p[2 * nd[3]])) * inv_h;
  const double ey =
      0.5 * ((p[2 * nd[1] + 1] + p[2 * nd[2] + 1]) - (p[2 * nd[0] + 1] + p[2 * nd[3] + 1])) * inv_h;
  const CrackConstants& k = d.crack_laws[d.cracks.material[c]];
  double tau[3];
  for (int i = 0; i < 3; ++i) {
    const double damage = d.cracks.damage[3 * c + i];
    const double sigma_c = o[i] < 0.0 ? k.pn * o[i] * inv_h : 0.0;
    const double fp = JointLaw::peak_strength(k, sigma_c);
    const double fr = -sigma_c * k.tan_phi_r;
    const double z = JointLaw::softening(damage);
    tau[i] = fp > 0.0
                 ? std::copysign(
                       pre_peak(std::fabs(s[i]) * inv_h * k.half_pt / fp) * (1.0 - z) * fr, s[i])
                 : 0.0;
  }
  const double w_end = h / 6.0, w_mid = h / 3.0;
  const double st0 = w_end * tau[0] + w_mid * tau[1], st1 = w_end * tau[2] + w_mid * tau[1];
  f[0] = -st0 * ex;
  f[1] = -st0 * ey;
  f[2] = -st1 * ex;
  f[3] = -st1 * ey;
}

/// f . (v_0 - v_3, v_1 - v_2): the power of forces f on element c's nodes
/// at the current velocities.
double power(const EngineData& d, std::size_t c, const double* f) {
  const int* nd = &d.cracks.nodes[4 * c];
  const double* v = d.nodes.vel.data();
  return f[0] * (v[2 * nd[0]] - v[2 * nd[3]]) + f[1] * (v[2 * nd[0] + 1] - v[2 * nd[3] + 1]) +
         f[2] * (v[2 * nd[1]] - v[2 * nd[2]]) + f[3] * (v[2 * nd[1] + 1] - v[2 * nd[2] + 1]);
}

bool any_joint_law(const EngineData& d) {
  return std::any_of(d.crack_laws.begin(), d.crack_laws.end(),
                     [](const CrackConstants& k) { return k.law == CrackLaw::kJoint; });
}

}  // namespace

void init_joint_friction(EngineData& d) {
  auto& cr = d.cracks;
  cr.joints.clear();
  if (any_joint_law(d))
    for (std::size_t c = 0; c < cr.size(); ++c)
      if (is_joint(d, c)) cr.joints.push_back(static_cast<int>(c));
  cr.joint_force.assign(4 * cr.joints.size(), 0.0);
}

void update_joint_list(EngineData& d, std::size_t c) {
  auto& list = d.cracks.joints;
  if (!any_joint_law(d)) return;
  const auto it = std::lower_bound(list.begin(), list.end(), static_cast<int>(c));
  const bool listed = it != list.end() && *it == static_cast<int>(c);
  // The kept forces follow the list: an element listed anew starts from none.
  auto kept = d.cracks.joint_force.begin() + 4 * (it - list.begin());
  if (is_joint(d, c) && !listed) {
    d.cracks.joint_force.insert(kept, 4, 0.0);
    list.insert(it, static_cast<int>(c));
  }
  if (!is_joint(d, c) && listed) {
    d.cracks.joint_force.erase(kept, kept + 4);
    list.erase(it);
  }
}

void book_joint_friction(EngineData& d) {
  const auto& list = d.cracks.joints;
  if (list.empty()) return;
  double* kept = d.cracks.joint_force.data();
  const double half_prev = 0.5 * d.energy.last_dt, half = 0.5 * d.dt;
  const double work = block_sum(static_cast<long>(list.size()), d.threads, [&](long i) {
    const std::size_t c = static_cast<std::size_t>(list[i]);
    double f[4];
    residual_friction_force(d, c, f);
    double* old = kept + 4 * i;
    const double w = power(d, c, old) * half_prev + power(d, c, f) * half;
    for (int k = 0; k < 4; ++k) old[k] = f[k];
    return w;
  });
  d.energy.joint_friction -= work;  // the forces resist: their work is dissipated
}

double joint_friction_pending(const EngineData& d) {
  const auto& list = d.cracks.joints;
  if (list.empty()) return 0.0;
  const double half = 0.5 * d.energy.last_dt;
  return -half * block_sum(static_cast<long>(list.size()), d.threads, [&](long i) {
    const std::size_t c = static_cast<std::size_t>(list[i]);
    return power(d, c, &d.cracks.joint_force[4 * i]);
  });
}

}  // namespace rockfdem::fdem::detail
