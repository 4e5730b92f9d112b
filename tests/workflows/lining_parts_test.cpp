// The lining ring's floor part of its own (tunnel.invert_thickness,
// [materials.invert]) on lined_invert_horseshoe.toml: a 6 x 5 m horseshoe
// with a flat floor, 0.2 m of shotcrete on the arch and walls and a 0.4 m
// concrete invert.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "rockfdem/mesh/build.hpp"
#include "rockfdem/mesh/outline.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "run/engine_setup.hpp"

namespace fs = std::filesystem;
namespace rt = rockfdem::test;
using namespace rockfdem;

namespace {

const std::string kScene = rt::kTestDir + "/lined_invert_horseshoe.toml";

double triangle_area(const mesh::Mesh& m, std::size_t t) { return std::abs(signed_area(m, t)); }

double centroid_y(const mesh::Mesh& m, std::size_t t) {
  const auto& v = m.triangles[t];
  return (m.y[std::size_t(v[0])] + m.y[std::size_t(v[1])] + m.y[std::size_t(v[2])]) / 3;
}

struct Segment {
  double y, thickness, thrust, moment, safety;
  bool corner;
};

std::vector<Segment> read_segments(const fs::path& p) {
  std::vector<Segment> out;
  for (const std::vector<double>& v : rt::numeric_rows(rt::read_text(p)))
    out.push_back({v.at(5), v.at(6), v.at(7) * 1e3, v.at(8) * 1e3, v.at(11), v.at(12) != 0});
  return out;
}

// The plain section's factor: extreme fibre stress N/t +- 6M/t^2 at fc or -ft.
double section_factor(double n, double m, double t, double fc, double ft) {
  const double mean = n / t, bending = 6 * std::abs(m) / (t * t);
  double fs = INFINITY;
  if (mean + bending > 0) fs = std::min(fs, fc / (mean + bending));
  if (mean - bending < 0) fs = std::min(fs, ft / (bending - mean));
  return fs;
}

}  // namespace

// The floor part is the ring below the inner walls' feet: with a flat floor
// a band span x invert_thickness (the corners included). The band's top is
// no mesh line where it crosses the walls' 0.2 m strips, so triangles are
// sorted by their centroids there: the band's area within the two corners'
// straddling elements (2 x 0.2 x 0.1 m^2 / 2; measured 5.4e-4 m^2). Its triangles take
// [materials.invert]'s modulus in the engine, the rest of the ring the lining's; the rest's area is
// the ring's between the opening and the inner outline (arcs within gmsh's chords).
TEST(LiningParts, floor_part_takes_the_invert_material_over_its_exact_band) {
  const workflows::Scene s = workflows::load_scene(kScene);
  ASSERT_TRUE(s.invert);
  const mesh::Mesh m = mesh::build_mesh(s.mesh);
  insitu::InsituField handoff;
  handoff.stress.resize(m.n_triangles());
  const fdem::ModelInput in = workflows::engine_input(s, m, handoff, 1);
  const double top = mesh::invert_part_top(s.mesh.tunnel);
  EXPECT_NEAR(top, -2.5 + 0.4, 1e-12);
  double floor_area = 0, rest_area = 0;
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (m.zone[t] != mesh::kLining) continue;
    const double young = in.materials[std::size_t(in.material[t])].young;
    if (centroid_y(m, t) < top) {
      EXPECT_EQ(young, 30e9) << t;
      floor_area += triangle_area(m, t);
    } else {
      EXPECT_EQ(young, 10e9) << t;
      rest_area += triangle_area(m, t);
    }
  }
  EXPECT_NEAR(floor_area, 6.0 * 0.4, 0.02);
  const double ring = mesh::outline_area(mesh::tunnel_outline(s.mesh.tunnel)) -
                      mesh::outline_area(mesh::lining_inner_outline(s.mesh.tunnel));
  EXPECT_NEAR(rest_area, ring - 6.0 * 0.4, 2e-3 * ring);
}

// The run's ring: the floor part's segments are 0.4 m thick and checked
// against the invert's strengths, the others 0.2 m against the lining's;
// each factor in lining.csv is the plain section's of its own N and M, and
// the summary's smallest factor is the file's.
TEST(LiningParts, each_part_is_checked_with_its_own_section) {
  const fs::path out = rt::scratch("lining_parts");
  const rt::Result r = rt::run("run " + kScene + " -q -j 1 -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json j = rt::read_json(out / "summary.json");
  ASSERT_EQ(j["status"], "completed") << j.dump(1);
  const std::vector<Segment> rows = read_segments(out / "lining.csv");
  double fs_min = INFINITY;
  int floor = 0;
  for (const Segment& g : rows) {
    fs_min = std::min(fs_min, g.safety);
    if (g.corner) continue;
    const bool in_floor = g.y < -2.1;
    floor += in_floor;
    EXPECT_NEAR(g.thickness, in_floor ? 0.4 : 0.2, 0.01) << g.y;
    const double fs = in_floor ? section_factor(g.thrust, g.moment, g.thickness, 40e6, 3e6)
                               : section_factor(g.thrust, g.moment, g.thickness, 20e6, 2e6);
    EXPECT_NEAR(g.safety, fs, 1e-4 * fs) << g.y;
  }
  EXPECT_GT(floor, 20);
  const nlohmann::json& l = j["lining"];
  EXPECT_NEAR(l["invert_thickness_m"].get<double>(), 0.4, 0.01);
  EXPECT_NEAR(l["thickness_m"].get<double>(), 0.2, 0.01);
  EXPECT_EQ(l["invert_compressive_strength_Pa"].get<double>(), 40e6);
  EXPECT_EQ(l["compressive_strength_Pa"].get<double>(), 20e6);
  EXPECT_NEAR(l["min_safety_factor"].get<double>(), fs_min, 1e-4 * fs_min);
  // Below 1 in the invert: the run says its support is overstressed, there.
  ASSERT_LT(fs_min, 1);
  EXPECT_EQ(j["support"]["verdict"], "overstressed");
  const std::string line = j["support"]["line"];
  EXPECT_EQ(line.rfind("support overstressed: lining invert SF ", 0), 0u) << line;
  EXPECT_NE(rt::read_text(out / "report.md").find("**Support overstressed**"), std::string::npos);
  fs::remove_all(out);
}

// A floor part of the lining's own thickness and material is the ring
// without one: the same state, bit for bit.
TEST(LiningParts, a_floor_part_like_the_rest_changes_nothing) {
  const fs::path dir = rt::scratch("lining_parts_same");
  fs::create_directories(dir);
  std::string text = rt::read_text(kScene);
  const auto cut = text.find("[materials.invert]");
  const auto next = text.find("[insitu]");
  ASSERT_NE(cut, std::string::npos);
  const std::string lining_like =
      "[materials.invert]\nyoung = 10.0e9\npoisson = 0.2\n"
      "tensile_strength = 2.0e6\ncompressive_strength = 20.0e6\n\n";
  for (const std::string& part : {lining_like, std::string()}) {
    std::string t = text.substr(0, cut) + part + text.substr(next);
    const auto k = t.find("invert_thickness = 0.4");
    ASSERT_NE(k, std::string::npos);
    t.replace(k, 22, "invert_thickness = 0.2");
    std::ofstream(dir / (part.empty() ? "none.toml" : "same.toml")) << t;
  }
  std::string hash[2];
  int i = 0;
  for (const char* name : {"same", "none"}) {
    const fs::path out = dir / (std::string(name) + "_out");
    const rt::Result r = rt::run("run " + (dir / (std::string(name) + ".toml")).string() +
                                 " -q -j 1 --set stages[3].max_steps=2000 -o " + out.string());
    ASSERT_EQ(r.code, 0) << r.output;
    hash[i++] = rt::read_json(out / "summary.json")["state_hash"].get<std::string>();
  }
  EXPECT_EQ(hash[0], hash[1]);
  fs::remove_all(dir);
}
