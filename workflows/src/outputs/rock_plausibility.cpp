#include "outputs/rock_plausibility.hpp"

#include <cmath>
#include <cstdio>

#include "outputs/broken_zone.hpp"

namespace rockfdem::workflows {
namespace {

PlausibilityFigure figure(const char* name, double value, double lo, double hi,
                          const char* meaning) {
  return {name, value, lo, hi, value >= lo && value <= hi, meaning};
}

}  // namespace

RockPlausibilityFigures rock_plausibility(const MaterialSpec& rock, double h_over_l_ch) {
  RockPlausibilityFigures p;
  if (rock.cohesion > 0) {
    p.ucs_Pa = mohr_coulomb_ucs(rock.cohesion, rock.friction_angle);
    p.figures.push_back(figure("ucs_over_young", *p.ucs_Pa / rock.young, 0.001, 0.01,
                               "intact rock's E / UCS lies between 100 and 1000"));
    if (rock.tensile_strength > 0)
      p.figures.push_back(figure("ft_over_ucs", rock.tensile_strength / *p.ucs_Pa, 0.03, 0.25,
                                 "Hoek-Brown ft ~ UCS / mi, mi from 4 to 33"));
  }
  if (h_over_l_ch > 0)
    p.figures.push_back(figure("h_over_l_ch", h_over_l_ch, 0, kResolutionLimit,
                               "larger: the crack pattern depends on the mesh"));
  return p;
}

RockPlausibilityFigures rock_plausibility(const Scene& scene, double h_over_l_ch) {
  if (!scene.rock_mass) return rock_plausibility(scene.materials.at(mesh::kRock), h_over_l_ch);
  RockPlausibilityFigures p = rock_plausibility(scene.rock_mass->lab, h_over_l_ch);
  p.of =
      "the laboratory set (materials.rock as given; the model's rock is the rock mass of "
      "GSI " +
      std::to_string(int(std::lround(scene.rock_mass->gsi))) + " derived from it)";
  return p;
}

std::vector<std::string> plausibility_warnings(const RockPlausibilityFigures& p,
                                               bool with_resolution) {
  std::vector<std::string> lines;
  for (const PlausibilityFigure& f : p.figures) {
    if (f.in_range || (!with_resolution && f.name == "h_over_l_ch")) continue;
    char text[400];
    std::snprintf(text, sizeof text,
                  "the rock's %s = %.3g is outside [%g, %g] (%s): no intact rock has this set "
                  "(a rock mass's figures: give the lab set with materials.rock.gsi)",
                  f.name.c_str(), f.value, f.low, f.high, f.meaning.c_str());
    lines.emplace_back(text);
  }
  return lines;
}

}  // namespace rockfdem::workflows
