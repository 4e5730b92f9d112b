// Seeded strength heterogeneity of rock crack elements (Material::
// weibull_modulus): one Weibull factor per element, scaling its tensile
// strength and cohesion (crack_law_parts.hpp, scaled_strength_terms).
//
// The factor is a pure function of (seed, the element's two mesh vertex
// ids, sorted): a counter-based hash (splitmix64) gives a uniform u in
// [0, 1), and the Weibull quantile of shape m and mean 1,
//   k = lambda (-ln(1 - u))^(1/m),   lambda = 1 / Gamma(1 + 1/m),
// clamped to [kMinStrengthFactor, kMaxStrengthFactor], turns it into the
// factor. Nothing depends on the thread count, on the order in which the
// elements are built or on the engine's node numbers, and a rejoined or
// re-assigned element draws again with its new material.
#pragma once

#include <cstddef>
#include <cstdint>

#include "engine_data.hpp"

namespace rockfdem::fdem::detail {

/// splitmix64's output function of x (Steele, Lea and Flood 2014).
std::uint64_t splitmix64(std::uint64_t x);

/// Strength factor of a crack element of material m on the mesh edge
/// (vertex_a, vertex_b): 1 when m is homogeneous (weibull_modulus = 0) or
/// not of the rock law.
double strength_factor(const Material& m, int vertex_a, int vertex_b);

/// Sets crack element c's factor from its current material. The per-element
/// array stays empty while every factor is 1 (no cost in the crack loop).
void assign_strength_factor(EngineData& d, std::size_t c);

/// assign_strength_factor for every crack element (construction).
void assign_strength_factors(EngineData& d);

/// Law constants of crack element c: its material's, strengths scaled by
/// its factor.
inline CrackConstants crack_constants(const EngineData& d, std::size_t c) {
  const CrackConstants& k = d.crack_laws[d.cracks.material[c]];
  return d.cracks.strength.empty() ? k : scale_crack_strength(k, d.cracks.strength[c]);
}

}  // namespace rockfdem::fdem::detail
