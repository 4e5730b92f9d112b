// The Mohr-Coulomb ground reaction curve of the continuum counterpart
// (workflows/src/run/continuum_ground_reaction.hpp) against Salencon's
// closed form (1969) with the wall displacement of the flow rule of
// dilation psi (Carranza-Torres and Fairhurst 2000; docs/insitu.md,
// plastic_ring): a circular opening (a = 3 m) in hydrostatic p0 = 10 MPa,
// E 5 GPa, nu 0.25, c 1.5 MPa, phi 30 deg: p_cr = 3.70 MPa, so of the
// curve's 20 pressures (1 - lambda) p0, those below p_cr (lambda 0.65 to 1)
// are plastic (R_pl = 4.67 m at the open hole) and those above are Lame's.
// The mesh: elastic_circular.toml's (0.3 m at the wall, 63 edges round it,
// a 100 m box), the wall's mean inward displacement over its vertices.
// Within 3% at every pressure (measured: printed).
#include "run/continuum_ground_reaction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "rockfdem/insitu/plastic.hpp"
#include "rockfdem/mesh/build.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {
namespace {

const std::string kDir = ROCKFDEM_WORKFLOWS_TEST_DIR;

/// Every rock vertex on the wall (touching the core), pointing inward.
std::vector<WallPoint> wall_points(const mesh::Mesh& m) {
  std::vector<std::uint8_t> rock(m.n_vertices(), 0), core(m.n_vertices(), 0);
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    for (const int v : m.triangles[t]) (m.zone[t] == mesh::kRock ? rock : core)[std::size_t(v)] = 1;
  std::vector<WallPoint> w;
  for (std::size_t v = 0; v < m.n_vertices(); ++v) {
    if (!rock[v] || !core[v]) continue;
    const double r = std::hypot(m.x[v], m.y[v]);
    w.push_back({"w" + std::to_string(v), int(v), -m.x[v] / r, -m.y[v] / r});
  }
  return w;
}

void follows_salencon(double psi, double size_near) {
  const double p0 = 10e6, a = 3, young = 5e9, nu = 0.25, c = 1.5e6, phi = 30;
  const Scene s =
      load_scene(kDir + "/elastic_circular.toml",
                 {"insitu.sigma_h=10e6", "insitu.sigma_v=10e6", "insitu.continuum=\"mohr_coulomb\"",
                  "materials.rock.cohesion=1.5e6", "materials.rock.friction_angle=30",
                  "insitu.dilation_angle=" + std::to_string(psi),
                  "mesh.size_near=" + std::to_string(size_near)});
  const mesh::Mesh m = mesh::build_mesh(s.mesh);
  const std::vector<WallPoint> wall = wall_points(m);
  ASSERT_GT(wall.size(), 50u);
  const auto curve = mohr_coulomb_ground_reaction(s, m, wall);
  ASSERT_EQ(curve.size(), 20u);  // the ground stands to the open hole
  int plastic = 0, elastic = 0;
  for (const ContinuumGroundReactionPoint& p : curve) {
    double u = 0, pressure = 0;
    for (const auto& [name, k] : p.key_points) {
      u += 1e-3 * k.radial_mm;
      pressure += k.pressure_Pa;
    }
    u /= double(p.key_points.size());
    pressure /= double(p.key_points.size());
    EXPECT_NEAR(pressure, (1 - p.lambda) * p0, 1e-6 * p0);
    insitu::PlasticRingCase rc;
    rc.a = a;
    rc.p0 = p0;
    rc.pi = pressure;
    rc.E = young;
    rc.nu = nu;
    rc.strength = {c, phi, psi};
    const insitu::PlasticRingSolution closed = insitu::plastic_ring(rc);
    (pressure < closed.critical_pressure ? plastic : elastic) += 1;
    std::printf("  psi %.0f, p_i %.2f MPa: u %.3f mm, closed form %.3f mm (%+.2f%%), R_pl %.2f m\n",
                psi, 1e-6 * pressure, 1e3 * u, 1e3 * closed.wall_displacement,
                100 * (u / closed.wall_displacement - 1), closed.plastic_radius);
    EXPECT_NEAR(u, closed.wall_displacement, 0.03 * closed.wall_displacement)
        << "p_i = " << pressure;
  }
  EXPECT_GE(plastic, 7);
  EXPECT_GE(elastic, 12);
}

TEST(ContinuumGroundReaction, follows_salencon_without_dilation) { follows_salencon(0, 0.3); }

TEST(ContinuumGroundReaction, follows_salencon_with_dilation) { follows_salencon(15, 0.2); }

}  // namespace
}  // namespace rockfdem::workflows
