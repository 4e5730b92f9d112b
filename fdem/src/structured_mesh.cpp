// Structured rectangle meshes for tests and benchmarks (no gmsh needed).
#include "rockfdem/fdem/structured_mesh.hpp"

#include <algorithm>
#include <cmath>

#include "rockfdem/error.hpp"

namespace rockfdem::fdem {

Material benchmark_rock() {
  Material m;
  m.density = 2700;
  m.young = 30e9;
  m.poisson = 0.25;
  m.tensile_strength = 5e6;
  m.cohesion = 15e6;
  m.friction_deg = 30;
  m.gf_I = 10;
  m.gf_II = 50;
  return m;
}

ModelInput structured_rectangle(const RectangleSpec& s, const Material& material) {
  if (s.nx < 1 || s.ny < 1 || !(s.width > 0) || !(s.height > 0))
    throw InputError("fdem structured mesh: needs nx, ny >= 1 and positive width and height");
  ModelInput in;
  const int nvx = s.nx + 1;
  for (int j = 0; j <= s.ny; ++j)
    for (int i = 0; i <= s.nx; ++i) {
      in.x.push_back(s.x0 + s.width * i / s.nx);
      in.y.push_back(s.y0 + s.height * j / s.ny);
    }
  auto v = [nvx](int i, int j) { return j * nvx + i; };
  for (int j = 0; j < s.ny; ++j)
    for (int i = 0; i < s.nx; ++i) {
      const int a = v(i, j), b = v(i + 1, j), c = v(i + 1, j + 1), d = v(i, j + 1);
      if ((i + j) % 2 == 0) {  // diagonal a-c
        in.triangles.push_back({a, b, c});
        in.triangles.push_back({a, c, d});
      } else {  // diagonal b-d
        in.triangles.push_back({a, b, d});
        in.triangles.push_back({b, c, d});
      }
    }
  in.material.assign(in.triangles.size(), 0);
  in.fracture.assign(in.triangles.size(), s.fracture ? 1 : 0);
  in.materials = {material};
  for (int i = 0; i < s.nx; ++i) {
    in.edges.push_back({v(i, 0), v(i + 1, 0), kTagBottom});
    in.edges.push_back({v(i + 1, s.ny), v(i, s.ny), kTagTop});
  }
  for (int j = 0; j < s.ny; ++j) {
    in.edges.push_back({v(s.nx, j), v(s.nx, j + 1), kTagRight});
    in.edges.push_back({v(0, j + 1), v(0, j), kTagLeft});
  }
  return in;
}

ModelInput ucs_specimen(const RectangleSpec& spec, const Material& material,
                        double platen_velocity) {
  ModelInput in = structured_rectangle(spec, material);
  BoundaryCondition bottom, top;
  bottom.tag = kTagBottom;
  top.tag = kTagTop;
  bottom.x = top.x = Constraint::kFixed;
  bottom.y = top.y = Constraint::kVelocity;
  bottom.vy = platen_velocity;
  top.vy = -platen_velocity;
  in.boundary_conditions = {bottom, top};
  return in;
}

RectangleSpec ucs_grid(double width, double height, long n_triangles) {
  RectangleSpec s;
  s.width = width;
  s.height = height;
  const double ratio = height / width;
  s.nx = std::max(1, static_cast<int>(std::lround(std::sqrt(n_triangles / (2.0 * ratio)))));
  s.ny = std::max(1, static_cast<int>(std::lround(s.nx * ratio)));
  return s;
}

std::vector<BoundaryCondition> rollers_with_top_traction(double ty) {
  BoundaryCondition bottom, left, top;
  bottom.tag = kTagBottom;
  bottom.y = Constraint::kFixed;
  left.tag = kTagLeft;
  left.x = Constraint::kFixed;
  top.tag = kTagTop;
  top.ty = ty;
  return {bottom, left, top};
}

}  // namespace rockfdem::fdem
