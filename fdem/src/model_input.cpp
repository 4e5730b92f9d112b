// Validation of the ModelInput record. Every message names the offending
// item and value and says what is allowed, so a scene author can fix it.
#include <cmath>
#include <sstream>
#include <string>

#include "rockfdem/error.hpp"
#include "rockfdem/fdem/crack_law.hpp"
#include "topology.hpp"

namespace rockfdem::fdem::detail {
namespace {

[[noreturn]] void fail(const std::string& what) { throw InputError("fdem model input: " + what); }

template <class T>
std::string str(const T& v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

void check_material(const Material& m, std::size_t i) {
  const std::string name = "material " + str(i) + ": ";
  if (!(m.density > 0)) fail(name + "density " + str(m.density) + " must be > 0");
  if (!(m.young > 0)) fail(name + "Young's modulus " + str(m.young) + " must be > 0");
  if (!(m.poisson > -1 && m.poisson < 0.5))
    fail(name + "Poisson ratio " + str(m.poisson) + " must lie in (-1, 0.5)");
  if (!(m.damping_ratio >= 0)) fail(name + "damping ratio must be >= 0");
  if (m.normal_penalty < 0 || m.tangential_penalty < 0)
    fail(name + "penalties must be >= 0 (0 selects 10 E)");
  if (!(m.gf_I > 0 && m.gf_II > 0)) fail(name + "fracture energies GfI, GfII must be > 0");
  if (!(m.weibull_modulus >= 0) || !std::isfinite(m.weibull_modulus))
    fail(name + "Weibull modulus " + str(m.weibull_modulus) +
         " must be >= 0 (0 = homogeneous strengths)");
  with_crack_law(m.crack_law, [&](auto law) {
    using Law = decltype(law);
    if (m.weibull_modulus > 0 && !Law::kHeterogeneous)
      fail(name +
           "a Weibull modulus (strength heterogeneity) applies to the rock crack law "
           "only; set it to 0 for " +
           Law::kName);
    const std::string problem = Law::input_problem(m);
    if (!problem.empty()) fail(name + problem);
  });
}

void check_sizes(const ModelInput& in) {
  const std::size_t nv = in.x.size(), nt = in.triangles.size();
  if (in.y.size() != nv) fail("x and y hold " + str(nv) + " and " + str(in.y.size()) + " values");
  if (nt == 0) fail("no triangles");
  if (in.material.size() != nt)
    fail("material has " + str(in.material.size()) + " entries for " + str(nt) + " triangles");
  if (!in.fracture.empty() && in.fracture.size() != nt)
    fail("fracture has " + str(in.fracture.size()) + " entries for " + str(nt) +
         " triangles (leave it empty for none)");
  if (!in.initial_stress.empty() && in.initial_stress.size() != nt)
    fail("initial_stress has " + str(in.initial_stress.size()) + " entries for " + str(nt) +
         " triangles");
  if (!in.initial_displacement.empty() && in.initial_displacement.size() != nv)
    fail("initial_displacement has " + str(in.initial_displacement.size()) + " entries for " +
         str(nv) + " vertices");
  if (in.materials.empty()) fail("no materials");
  if (in.materials.size() > 65535) fail("more than 65535 materials");
}

void check_triangles(const ModelInput& in) {
  const int nv = static_cast<int>(in.x.size());
  const int nm = static_cast<int>(in.materials.size());
  for (std::size_t t = 0; t < in.triangles.size(); ++t) {
    const auto& v = in.triangles[t];
    for (int k = 0; k < 3; ++k)
      if (v[k] < 0 || v[k] >= nv)
        fail("triangle " + str(t) + " has vertex " + str(v[k]) + " outside [0, " + str(nv) + ")");
    const double area = (in.x[v[1]] - in.x[v[0]]) * (in.y[v[2]] - in.y[v[0]]) -
                        (in.x[v[2]] - in.x[v[0]]) * (in.y[v[1]] - in.y[v[0]]);
    if (!(area > 0))
      fail("triangle " + str(t) + " is not counter-clockwise (twice its signed area is " +
           str(area) + "); reorder its vertices");
    if (in.material[t] < 0 || in.material[t] >= nm)
      fail("triangle " + str(t) + " has material " + str(in.material[t]) + " outside [0, " +
           str(nm) + ")");
  }
}

void check_edges_and_bcs(const ModelInput& in) {
  const int nv = static_cast<int>(in.x.size());
  for (std::size_t e = 0; e < in.edges.size(); ++e) {
    const auto& g = in.edges[e];
    if (g.a < 0 || g.a >= nv || g.b < 0 || g.b >= nv || g.a == g.b)
      fail("tagged edge " + str(e) + " (" + str(g.a) + ", " + str(g.b) + ") is not a mesh edge");
  }
  for (const auto& bc : in.boundary_conditions) {
    bool found = false;
    for (const auto& g : in.edges) found = found || g.tag == bc.tag;
    if (!found) fail("boundary condition for tag " + str(bc.tag) + " but no edge carries it");
  }
  if (!(in.dt >= 0)) fail("dt " + str(in.dt) + " must be >= 0 (0 = automatic)");
  if (!(in.dt_safety > 0 && in.dt_safety <= 1))
    fail("dt_safety " + str(in.dt_safety) + " must lie in (0, 1]");
  if (!(in.damping.local >= 0 && in.damping.local < 1))
    fail("local damping " + str(in.damping.local) + " must lie in [0, 1)");
  if (!(in.damping.mass_proportional >= 0)) fail("mass-proportional damping must be >= 0");
  if (!(in.mass_scaling.dt >= 0) || !std::isfinite(in.mass_scaling.dt))
    fail("mass scaling dt " + str(in.mass_scaling.dt) +
         " s must be >= 0 (0 selects the least constrained node's own limit)");
  if (in.threads < 0) fail("threads must be >= 0 (0 = OpenMP default)");
}

}  // namespace

void validate_input(const ModelInput& in) {
  check_sizes(in);
  for (std::size_t i = 0; i < in.materials.size(); ++i) check_material(in.materials[i], i);
  check_triangles(in);
  check_edges_and_bcs(in);
}

}  // namespace rockfdem::fdem::detail
