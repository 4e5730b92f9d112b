// The joint crack law (crack_law_joint.hpp) through the engine: direct shear
// against Mohr-Coulomb peak and residual strength, free opening without
// tensile strength, and a crown wedge against its limit equilibrium.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "rockfdem/fdem/constants.hpp"
#include "rockfdem/fdem/crack_law.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "test_models.hpp"

namespace rockfdem::fdem {
namespace {

/// Joint of the tests: ft = 0, c = 0.5 MPa, phi = 35, phi_r = 25 degrees,
/// GfII = 100 J/m^2, penalties 10 E of the rock.
Material joint() {
  Material m = test::rock();
  m.crack_law = CrackLaw::kJoint;
  m.tensile_strength = 0;
  m.cohesion = 0.5e6;
  m.friction_deg = 35;
  m.residual_friction_deg = 25;
  m.gf_II = 100;
  return m;
}

double tan_deg(double deg) { return std::tan(deg * kPi / 180.0); }

struct ShearCurve {
  double peak = 0;      ///< largest shear stress [Pa]
  double residual = 0;  ///< shear stress at the end [Pa]
  double normal = 0;    ///< normal stress at the end [Pa], compression positive
};

/// Direct shear of the two-triangle joint: the upper triangle is pressed
/// down by `closure`, then translated along the joint to `slip` in n
/// increments; stresses from the nodal forces over the joint length h.
ShearCurve direct_shear(const Material& m, double h, double closure, double slip, int n) {
  ModelInput in = test::two_triangles(h, m);
  Engine e(in);
  const auto top = e.triangle_nodes(1), bottom = e.triangle_nodes(0);
  ShearCurve c;
  for (int i = 0; i <= n; ++i) {
    const double u = slip * i / n;
    for (int k = 0; k < 3; ++k) {
      const int v = e.node_vertex()[top[k]], w = e.node_vertex()[bottom[k]];
      e.set_node_state(top[k], in.x[v] + u, in.y[v] - closure, 0, 0);
      e.set_node_state(bottom[k], in.x[w], in.y[w], 0, 0);
    }
    e.step();
    double fx = 0, fy = 0;
    for (int node : top) {
      fx += e.node_force(node)[0];
      fy += e.node_force(node)[1];
    }
    c.peak = std::max(c.peak, -fx / h);
    c.residual = -fx / h;
    c.normal = fy / h;
  }
  return c;
}

// Peak c + sigma tan(phi) and residual sigma tan(phi_r) at sigma = 2 MPa
// (closure sigma h / pn), slip to 1.5 x the end of the softening range.
TEST(JointLaw, direct_shear_follows_mohr_coulomb_peak_and_residual) {
  const Material m = joint();
  const double h = 0.1, sigma = 2e6;
  const CrackConstants k = make_crack_constants(m);
  const double fp = m.cohesion + sigma * tan_deg(m.friction_deg);
  const double end = 2 * h * fp / k.pt + k.slip_energy / fp;
  const ShearCurve c = direct_shear(m, h, sigma * h / k.pn, 1.5 * end, 3000);
  const double fr = sigma * tan_deg(m.residual_friction_deg);
  std::printf("direct shear: sigma %.4g, peak %.6g (Mohr-Coulomb %.6g), residual %.6g (%.6g)\n",
              c.normal, c.peak, fp, c.residual, fr);
  EXPECT_NEAR(c.normal, sigma, 1e-6 * sigma);
  EXPECT_NEAR(c.peak, fp, 0.02 * fp);
  EXPECT_NEAR(c.residual, fr, 0.02 * fr);
}

/// tau = sigma tan(phi_r + JRC log10(JCS / sigma)), the angle in
/// [phi_r, 70 deg]: the closed form the Barton-Bandis peak is tested against.
double barton_bandis(double sigma, double jrc, double jcs, double phi_r_deg) {
  const double angle = std::clamp(phi_r_deg + jrc * std::log10(jcs / sigma), phi_r_deg, 70.0);
  return sigma * tan_deg(angle);
}

// Barton-Bandis peak: the joint (no cohesion, phi_r = 25 deg) under direct
// shear at several normal stresses peaks at the closed form within 2% and
// ends at sigma tan(phi_r): JRC 10, JCS 50 MPa at 0.5, 2 and 8 MPa (total
// angles 45, 39 and 33 deg); JRC 20, JCS 100 MPa at 0.2 MPa (79 deg, capped
// at 70); JCS 5 MPa below the 8 MPa normal stress (angle held at phi_r).
TEST(JointLaw, direct_shear_peaks_at_the_barton_bandis_strength) {
  struct Case {
    double jrc, jcs, sigma;
  };
  const double h = 0.1;
  for (const Case& q : {Case{10, 50e6, 0.5e6}, Case{10, 50e6, 2e6}, Case{10, 50e6, 8e6},
                        Case{20, 100e6, 0.2e6}, Case{10, 5e6, 8e6}}) {
    Material m = joint();
    m.cohesion = 0;
    m.jrc = q.jrc;
    m.jcs = q.jcs;
    const CrackConstants k = make_crack_constants(m);
    const double fp = barton_bandis(q.sigma, q.jrc, q.jcs, m.residual_friction_deg);
    const double end = 2 * h * fp / k.pt + k.slip_energy / fp;
    const ShearCurve c = direct_shear(m, h, q.sigma * h / k.pn, 1.5 * end, 3000);
    const double fr = q.sigma * tan_deg(m.residual_friction_deg);
    std::printf(
        "Barton-Bandis JRC %g, JCS %.3g: sigma %.4g, peak %.6g (closed form %.6g), "
        "residual %.6g (%.6g)\n",
        q.jrc, q.jcs, c.normal, c.peak, fp, c.residual, fr);
    EXPECT_NEAR(c.normal, q.sigma, 1e-6 * q.sigma);
    EXPECT_NEAR(c.peak, fp, 0.02 * fp) << "JRC " << q.jrc << ", sigma " << q.sigma;
    EXPECT_NEAR(c.residual, fr, 0.02 * fr);
  }
  // The strength the pre-stress and the potential use is the same closed form,
  // c added; in tension it is c alone.
  Material m = joint();
  m.jrc = 10;
  m.jcs = 50e6;
  const CrackConstants k = make_crack_constants(m);
  EXPECT_NEAR(JointLaw::shear_strength(k, -2e6), m.cohesion + barton_bandis(2e6, 10, 50e6, 25),
              1e-9 * m.cohesion);
  EXPECT_EQ(JointLaw::shear_strength(k, 1e6), m.cohesion);
}

// Barton-Bandis input: JCS > 0, JRC in [0, 20], phi_r below the cap.
TEST(JointLaw, barton_bandis_input_is_checked) {
  Material m = joint();
  m.jrc = 10;
  m.jcs = 50e6;
  EXPECT_EQ(JointLaw::input_problem(m), "");
  m.jrc = 21;
  EXPECT_NE(JointLaw::input_problem(m).find("JRC"), std::string::npos);
  m.jrc = 10;
  m.jcs = -1;
  EXPECT_NE(JointLaw::input_problem(m).find("JCS"), std::string::npos);
  m.jcs = 0;  // JRC alone: JCS missing
  EXPECT_NE(JointLaw::input_problem(m).find("JCS"), std::string::npos);
}

// Without tensile strength and cohesion an open joint carries nothing and
// takes no damage; it never breaks.
TEST(JointLaw, open_joint_without_strength_carries_nothing) {
  Material m = joint();
  m.cohesion = 0;
  const double h = 0.1;
  ModelInput in = test::two_triangles(h, m);
  Engine e(in);
  const auto top = e.triangle_nodes(1);
  for (int k = 0; k < 3; ++k) {
    const int v = e.node_vertex()[top[k]];
    e.set_node_state(top[k], in.x[v] + 1e-3, in.y[v] + 1e-3, 0, 0);
  }
  e.step();
  for (int node : top) {  // round-off of the translated triangle only (1 MPa on h: 1e5 N/m)
    EXPECT_NEAR(e.node_force(node)[0], 0.0, 1e-3);
    EXPECT_NEAR(e.node_force(node)[1], 0.0, 1e-3);
  }
  EXPECT_EQ(e.crack_damage(0), 0.0);
  EXPECT_NE(e.crack_state(0), CrackState::kBroken);
}

// crack_displacement on an imposed motion: the upper triangle pressed down
// by a closure and slid along the joint; every point reports the slip and
// the (negative) opening, whichever face is first (positions of order h:
// round-off 1e-16 m, tolerance 1e-12 m). After a re-join at that position
// the positions' values are unchanged and the law's are zero but for the
// rounding of the offsets as stored (test::kStored of the slip and closure).
TEST(JointLaw, crack_displacement_reports_the_imposed_slip_and_closure) {
  const double h = 0.1, closure = 2e-5, slip = 3e-3;
  ModelInput in = test::two_triangles(h, joint());
  Engine e(in);
  const auto top = e.triangle_nodes(1);
  for (int k = 0; k < 3; ++k) {
    const int v = e.node_vertex()[top[k]];
    e.set_node_state(top[k], in.x[v] + slip, in.y[v] - closure, 0, 0);
  }
  // The sign of the slip: positive when the face on the left of the
  // element, looking along it, moves forward; here the upper face moves
  // along +x, and the joint runs along x either way round.
  const bool top_first = e.crack_triangles(0)[0] == 1;
  const std::array<int, 4> nodes = e.crack_nodes(0);
  const double along = e.positions()[2 * nodes[1]] - e.positions()[2 * nodes[0]];
  EXPECT_EQ(top_first, along > 0);
  const CrackDisplacement u = e.crack_displacement(0);
  EXPECT_NEAR(u.length, h, 1e-12);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(u.slip[i], slip, 1e-12);
    EXPECT_NEAR(u.opening[i], -closure, 1e-12);
    EXPECT_EQ(u.law_slip[i], u.slip[i]);
    EXPECT_EQ(u.law_opening[i], u.opening[i]);
  }
  e.rejoin_crack(0, 0);
  const CrackDisplacement r = e.crack_displacement(0);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(r.slip[i], u.slip[i]);
    EXPECT_NEAR(r.law_slip[i], 0.0, test::kStored * slip);
    EXPECT_NEAR(r.law_opening[i], 0.0, test::kStored * closure);
  }
}

}  // namespace
}  // namespace rockfdem::fdem
