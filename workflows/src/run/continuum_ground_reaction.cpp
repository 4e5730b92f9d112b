#include "run/continuum_ground_reaction.hpp"

#include "outputs/ground_reaction.hpp"
#include "rockfdem/insitu/plastic.hpp"
#include "run/engine_setup.hpp"

namespace rockfdem::workflows {

std::vector<ContinuumGroundReactionPoint> mohr_coulomb_ground_reaction(
    const Scene& scene, const mesh::Mesh& m, const std::vector<WallPoint>& points) {
  insitu::InsituSpec spec = insitu_spec(scene);
  spec.lining.active = false;
  const MaterialSpec& rock = scene.materials.at(mesh::kRock);
  insitu::PlasticSpec p;
  p.rock = {rock.cohesion, rock.friction_angle, scene.insitu.dilation_angle};
  // Reported at every step of the release (max_increment 0.05): the curve
  // costs no step beyond the release itself.
  const int n_steps = 20;
  p.release.clear();
  for (int i = 1; i <= n_steps; ++i) p.release.push_back(double(i) / n_steps);
  p.stop_at_failure = true;
  std::vector<ContinuumGroundReactionPoint> curve;
  for (const insitu::PlasticField& f : insitu::solve_mohr_coulomb(m, spec, p)) {
    ContinuumGroundReactionPoint& c = curve.emplace_back();
    c.lambda = f.lambda;
    for (const WallPoint& w : points) {
      const double u =
          f.ux[std::size_t(w.vertex)] * w.inward_x + f.uy[std::size_t(w.vertex)] * w.inward_y;
      c.key_points[w.name] = {
          1e3 * u, (1 - f.lambda) * insitu_normal_stress(scene.insitu, w.inward_x, w.inward_y)};
    }
  }
  return curve;
}

}  // namespace rockfdem::workflows
