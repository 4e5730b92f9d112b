#include "rockfdem/coupling/lining_cracks.hpp"

namespace rockfdem::coupling {

std::vector<std::size_t> lining_interface_cracks(const fdem::Engine& e, const mesh::Mesh& m) {
  std::vector<std::size_t> out;
  for (std::size_t c = 0; c < e.n_cracks(); ++c) {
    const auto t = e.crack_triangles(c);
    if ((m.zone[t[0]] == mesh::kLining) != (m.zone[t[1]] == mesh::kLining)) out.push_back(c);
  }
  return out;
}

}  // namespace rockfdem::coupling
