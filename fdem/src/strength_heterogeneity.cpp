// Strength factors of crack elements (strength_heterogeneity.hpp).
#include "strength_heterogeneity.hpp"

#include <algorithm>
#include <cmath>

namespace rockfdem::fdem::detail {

std::uint64_t splitmix64(std::uint64_t x) {
  std::uint64_t z = x + 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

double strength_factor(const Material& m, int vertex_a, int vertex_b) {
  if (!(m.weibull_modulus > 0) || !crack_law_heterogeneous(m.crack_law)) return 1.0;
  // The edge as one 64-bit counter (vertex ids are non-negative ints),
  // hashed together with the hashed seed.
  const auto lo = static_cast<std::uint64_t>(std::min(vertex_a, vertex_b));
  const auto hi = static_cast<std::uint64_t>(std::max(vertex_a, vertex_b));
  const std::uint64_t h = splitmix64(splitmix64(m.heterogeneity_seed) ^ ((hi << 32) | lo));
  const double u = static_cast<double>(h >> 11) * 0x1.0p-53;  // [0, 1), 53 bits
  const double inv_m = 1.0 / m.weibull_modulus;
  const double scale = 1.0 / std::tgamma(1.0 + inv_m);  // mean 1
  const double k = scale * std::pow(-std::log1p(-u), inv_m);
  return std::clamp(k, kMinStrengthFactor, kMaxStrengthFactor);
}

void assign_strength_factor(EngineData& d, std::size_t c) {
  const int* nd = &d.cracks.nodes[4 * c];  // nodes 0 and 1 sit on the edge's two vertices
  const double k = strength_factor(d.materials[d.cracks.material[c]], d.nodes.vertex[nd[0]],
                                   d.nodes.vertex[nd[1]]);
  auto& strength = d.cracks.strength;
  if (strength.empty()) {
    if (k == 1.0) return;
    strength.assign(d.cracks.size(), 1.0);
  }
  strength[c] = k;
}

void assign_strength_factors(EngineData& d) {
  for (std::size_t c = 0; c < d.cracks.size(); ++c) assign_strength_factor(d, c);
}

}  // namespace rockfdem::fdem::detail
