// Is the rock set one an experienced rock engineer would accept? Three
// dimensionless figures of the host rock's crack elements, each against
// the range real rock spans:
//
// - UCS / E, with UCS the crack elements' Mohr-Coulomb uniaxial strength
//   2 c cos(phi) / (1 - sin(phi)): intact rock's modulus ratio E / UCS lies
//   between 100 and 1000 (Deere and Miller 1966; Hoek and Diederichs 2006,
//   their MR table), so UCS / E within [0.001, 0.01]. A fit outside it is
//   an elastic back-analysis, not a rock.
// - ft / UCS: the Hoek-Brown estimate ft ~ UCS / mi with mi from 4
//   (claystone) to 33 (granite) (Hoek and Brown 1997), so [0.03, 0.25].
// - h / l_ch, the fracture zone's element size over Hillerborg's
//   characteristic length E GfI / ft^2: at most 1 (broken_zone.hpp), else
//   the crack pattern depends on the mesh.
#pragma once

#include "record/support_figures.hpp"
#include "rockfdem/workflows/rock_mass.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

/// The rock's plausibility figures; `h_over_l_ch` from fracture_resolution.
/// A figure whose inputs are not given (no cohesion, no tensile strength)
/// is left out.
RockPlausibilityFigures rock_plausibility(const MaterialSpec& rock, double h_over_l_ch);

/// The scene's rock judged: with materials.rock.gsi the laboratory set the
/// rock mass is derived from (a rock mass's ft / UCS is far below any
/// intact rock's by design), else the model's rock.
RockPlausibilityFigures rock_plausibility(const Scene& scene, double h_over_l_ch);

/// One line per figure outside its range, naming the figure, its value,
/// the range and what it means; empty when all are within. Without
/// `with_resolution` h / l_ch is left out (the caller warns of it with h).
std::vector<std::string> plausibility_warnings(const RockPlausibilityFigures& p,
                                               bool with_resolution = true);

}  // namespace rockfdem::workflows
