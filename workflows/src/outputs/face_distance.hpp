// Where the support goes in along the tunnel: the longitudinal displacement
// profile of Vlachopoulos and Diederichs (2009) turns a distance behind the
// face into the share of the final wall displacement the wall has made,
// and the implicit stage's ground reaction curve turns that share into the
// core's alpha (insitu.install_at_face_distance).
//
//   X* = X / R_t,  R* = R_p / R_t (R_p <= R_t: 1),  u0* = exp(-0.15 R*) / 3
//   X* <= 0 (ahead of the face):  u* = u0* exp(X*)
//   X* >= 0 (behind it):          u* = 1 - (1 - u0*) exp(-3 X* / (2 R*))
//
// R_t the tunnel's radius (here the equivalent circle's), R_p the plastic
// radius of the unsupported opening far behind the face (here Salencon's,
// docs/insitu.md, for the mean in-situ stress (sigma_h + sigma_v) / 2 and
// the rock's c, phi; cohesion not given: elastic ground, R* = 1).
#pragma once

#include <vector>

#include "outputs/implicit_sample.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

/// u*(X*, R*) above: the wall displacement over its final value.
double ldp_displacement_fraction(double x_star, double r_star);

/// The plastic radius of the unsupported equivalent circle of `radius`
/// (above) [m]; `radius` when the wall stays elastic or the rock has no
/// cohesion given.
double ldp_plastic_radius(const Scene& scene, double radius);

/// The alpha at which `u` reaches `fraction` of its value at alpha = 0:
/// `alphas` strictly decreasing and ending at 0, `u` the wall displacement
/// at each (growing as alpha falls); linear between neighbouring alphas.
double alpha_at_fraction(const std::vector<double>& alphas, const std::vector<double>& u,
                         double fraction);

/// The mean inward displacement of the opening's wall [m]: over the rock
/// vertices that touch the core or the lining, each displacement projected
/// on the direction from the vertex to (cx, cy).
double mean_wall_displacement(const mesh::Mesh& m, const insitu::InsituField& f, double cx,
                              double cy);

/// summary.json convergence_confinement.installation with a face distance.
struct FaceDistanceFigures {
  double face_distance_m = 0, radius_m = 0, plastic_radius_m = 0;
  double x_star = 0, r_star = 0, u_star = 0;
  double alpha = 0;  ///< the core's alpha where the support goes in
};

/// mean_wall_displacement about the centre of `m`'s equivalent opening.
double wall_displacement(const mesh::Mesh& m, const insitu::InsituField& f);

/// The scene's installation (insitu.install_at_face_distance): `curve` the
/// implicit fields' samples at alphas decreasing to 0.
FaceDistanceFigures face_distance_installation(const Scene& scene, const mesh::Mesh& m,
                                               const std::vector<ImplicitSample>& curve);

}  // namespace rockfdem::workflows
