#include "outputs/continuum_yield.hpp"

#include <set>

#include "outputs/picture_outlines.hpp"
#include "outputs/run_pictures.hpp"

namespace rockfdem::workflows {

plots::MeshPicture yield_picture(const mesh::Mesh& m, const std::vector<std::uint8_t>& yielded,
                                 const std::vector<std::uint8_t>& active) {
  plots::MeshPicture p;
  p.title = "Mohr-Coulomb continuum counterpart: yielded zone, end of the sequence";
  p.bar_title = "continuum";
  std::set<int> present;
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    const int code = m.zone[t] != mesh::kRock ? 2 : yielded[t] ? 1 : 0;
    p.values.push_back(code);
    p.hidden.push_back(!active.empty() && !active[t]);
    if (!p.hidden.back()) present.insert(code);
  }
  const char* names[] = {"rock, elastic", "rock, yielded", "lining"};
  for (const int code : present) p.categories.push_back({code, names[code]});
  p.view = opening_window(m);
  if (p.view) {
    plots::PictureLines edge = fracture_zone_lines(m, 0.01 * (p.view->x1 - p.view->x0));
    if (!edge.segments.empty()) p.lines.push_back(std::move(edge));
  }
  return p;
}

}  // namespace rockfdem::workflows
