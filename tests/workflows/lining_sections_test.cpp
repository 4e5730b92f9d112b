// The lining's section types (outputs/lining_sections.hpp): the reinforced
// section's M-N interaction diagram against a hand calculation, the steel
// sets' composite against a hand computation, the radial safety factor of
// points inside and outside a diagram, "plain" the default and unchanged,
// and the scene keys of the sections refused when wrong.
#include "outputs/lining_sections.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rw = rockfdem::workflows;
using rockfdem::test::error_of;

namespace {

// b = 1 m, h = 0.3 m, fck = 30 MPa; two layers of As = 1131 mm^2/m (12 mm
// bars at 100 mm) at 50 mm cover to their centroid; B500: fy = 500 MPa,
// Es = 200 GPa.
rw::LiningSection reinforced() {
  rw::LiningSection s;
  s.kind = rw::SectionKind::kReinforced;
  s.concrete = {30e6, 2.9e6};
  s.steel_young = 200e9;
  s.steel_yield = 500e6;
  s.bar_area = 1131e-6;
  s.bar_cover = 0.05;
  return s;
}
constexpr double kH = 0.3;

// The diagram's M at thrust n on its M > 0 side (linear between points).
double moment_at(const std::vector<rw::MNPoint>& d, double n) {
  for (std::size_t i = 0; i + 1 < d.size(); ++i) {
    const rw::MNPoint a = d[i], b = d[i + 1];
    if (a[0] < 0 || b[0] < 0 || (a[1] - n) * (b[1] - n) > 0 || a[1] == b[1]) continue;
    return a[0] + (b[0] - a[0]) * (n - a[1]) / (b[1] - a[1]);
  }
  return NAN;
}

// Young shotcrete (E 5 GPa, fc 30, ft 3 MPa, 0.25 m) with HEB 160 sets
// (A = 5.43e-3 m^2, I = 2.492e-5 m^4, depth 0.16 m, S275, 1 m apart).
rw::LiningSection steel_sets() {
  rw::LiningSection s;
  s.kind = rw::SectionKind::kSteelSets;
  s.concrete = {30e6, 3e6};
  s.concrete_young = 5e9;
  s.steel_young = 200e9;
  s.steel_yield = 275e6;
  s.set_area = 5.43e-3;
  s.set_inertia = 2.492e-5;
  s.set_depth = 0.16;
  s.set_spacing = 1.0;
  return s;
}
constexpr double kShotcrete = 0.25;

}  // namespace

// EN 1992-1-1 rectangular block for fck <= 50 MPa: eta = 1 over lambda x,
// lambda = 0.8, eps_cu3 = 3.5e-3 at the compressed face, eps_c3 = 1.75e-3
// in pure compression; no partial factors; M about mid-depth, y_s = 0.1 m.
//
// Pure compression, uniform eps_c3: the bars at Es eps_c3 = 350 MPa < fy,
//   N0 = fck b h + 2 As 350 MPa = 9000 + 791.7 = 9791.7 kN/m.
// Pure tension: both layers yielding, N = -2 As fy = -1131.0 kN/m.
// Balance (eps_cu3 at the face, the far bars at eps_y = fy / Es = 2.5e-3):
//   x_b = 3.5 / (3.5 + 2.5) d = 0.583333 x 0.25 = 0.145833 m,
//   C = 0.8 x 0.145833 x 30 MPa = 3500 kN; near bars eps = 3.5e-3 (1 - 0.05 /
//   0.145833) = 2.3e-3, 460 MPa, 520.26 kN; far bars -565.5 kN;
//   N_b = 3500 + 520.26 - 565.5 = 3454.76 kN/m,
//   M_b = 3500 (0.15 - 0.4 x 0.145833) + 0.1 (520.26 + 565.5) = 320.833 + 108.576
//       = 429.41 kNm/m.
// N = 0 (the far bars yield, the near ones stretched elastically as x < 0.05):
//   24e6 x + 1131e-6 x 700e6 (1 - 0.05 / x) - 565.5e3 = 0
//   -> 24e6 x^2 + 226.2e3 x - 39585 = 0, x = 0.0361725 m; C = 868.14 kN,
//   near bars eps = -1.338e-3, -267.59 MPa, -302.64 kN;
//   M0 = 868.14 (0.15 - 0.4 x 0.0361725) + 0.1 (-302.64 + 565.5)
//      = 117.66 + 26.29 = 143.95 kNm/m.
TEST(ReinforcedSection, diagram_matches_the_hand_calculation) {
  const auto d = rw::reinforced_diagram(reinforced(), kH);
  ASSERT_GT(d.size(), 100u);
  EXPECT_EQ(d.front(), d.back());
  double n_max = -INFINITY, n_min = INFINITY;
  for (const rw::MNPoint& p : d) n_max = std::max(n_max, p[1]), n_min = std::min(n_min, p[1]);
  EXPECT_NEAR(n_max, 9791.7e3, 0.01 * 9791.7e3);
  EXPECT_NEAR(n_min, -1131.0e3, 0.01 * 1131.0e3);
  EXPECT_NEAR(moment_at(d, 3454.76e3), 429.41e3, 0.01 * 429.41e3);
  EXPECT_NEAR(moment_at(d, 0), 143.95e3, 0.01 * 143.95e3);
  // Symmetric bars: the M < 0 side mirrors the M > 0 side.
  double m_max = 0, m_min = 0;
  for (const rw::MNPoint& p : d) m_max = std::max(m_max, p[0]), m_min = std::min(m_min, p[0]);
  EXPECT_NEAR(m_min, -m_max, 1e-9 * m_max);
}

// Radial factor: (N, M) scaled along the ray from the origin to the
// boundary. Hand values from the points above: half of pure compression
// is at FS 2 (the ray is the N axis), a third of M0 at N = 0 at FS 3, half
// the balance point at FS 2; 1.25 times the balance point outside, FS 0.8.
TEST(ReinforcedSection, safety_factor_is_the_ray_to_the_diagram) {
  const rw::LiningSection s = reinforced();
  const auto fs = [&](double n, double m) { return rw::section_safety_factor({n, m, 0}, kH, s); };
  EXPECT_NEAR(fs(9791.7e3 / 2, 0), 2.0, 0.01 * 2.0);
  EXPECT_NEAR(fs(0, 143.95e3 / 3), 3.0, 0.01 * 3.0);
  EXPECT_NEAR(fs(0, -143.95e3 / 3), 3.0, 0.01 * 3.0);
  EXPECT_NEAR(fs(3454.76e3 / 2, 429.41e3 / 2), 2.0, 0.01 * 2.0);
  EXPECT_NEAR(fs(1.25 * 3454.76e3, 1.25 * 429.41e3), 0.8, 0.01 * 0.8);
  EXPECT_NEAR(fs(-1131.0e3 / 4, 0), 4.0, 0.01 * 4.0);
  EXPECT_TRUE(std::isinf(fs(0, 0)));
}

// Shares by stiffness (per metre): EA_c = 5e9 x 0.25 = 1.25e9 N, EA_s =
// 200e9 x 5.43e-3 = 1.086e9 N; EI_c = 5e9 x 0.25^3 / 12 = 6.5104e6, EI_s =
// 200e9 x 2.492e-5 = 4.984e6 N m^2.
// Pure compression: both shortened alike, the sets yield first (eps_y =
// 275 / 200e3 = 1.375e-3; the shotcrete then at 6.9 MPa < fc):
//   N = (EA_c + EA_s) eps_y = 2.336e9 x 1.375e-3 = 3212.0 kN/m.
// Pure bending: both bent alike, the shotcrete's tensile fibre first (kappa
// = ft / (E_c t / 2) = 4.8e-3 /m; the sets' fibre then at 76.8 MPa < fy):
//   M = (EI_c + EI_s) kappa = 11.4944e6 x 4.8e-3 = 55.17 kNm/m.
// Pure tension: the shotcrete at -ft first: N = -2.336e9 x 6e-4 = -1401.6 kN/m.
TEST(SteelSetSection, composite_capacity_matches_the_hand_computation) {
  const rw::LiningSection s = steel_sets();
  const rw::CompositeShares k = rw::steel_set_shares(s, kShotcrete);
  EXPECT_NEAR(k.thrust, 1.086 / 2.336, 1e-12);
  EXPECT_NEAR(k.moment, 4.984 / (4.984 + 6.5104167), 1e-6);
  const auto fs = [&](double n, double m) {
    return rw::section_safety_factor({n, m, 0}, kShotcrete, s);
  };
  EXPECT_NEAR(fs(3212.0e3, 0), 1.0, 1e-4);
  EXPECT_NEAR(fs(0, 55.17e3), 1.0, 1e-3);
  EXPECT_NEAR(fs(0, -55.17e3 / 2), 2.0, 2e-3);
  EXPECT_NEAR(fs(-1401.6e3, 0), 1.0, 1e-4);
  // The plotted diagram is the same boundary: each part's limit in the
  // composite's forces, intersected.
  const auto d = rw::capacity_diagram(s, kShotcrete);
  for (const auto& [n, m] : {std::pair{3212.0e3, 0.0}, {1e6, 3e4}, {-2e5, -4e4}, {2e6, -1e5}})
    EXPECT_NEAR(rw::radial_safety_factor(d, {n, m, 0}), fs(n, m), 1e-9 * fs(n, m)) << n << m;
}

// "plain" given is the default: the same section, and its factor is the
// plain closed form of lining_forces.hpp, bit for bit.
TEST(PlainSection, plain_given_is_the_default_and_unchanged) {
  const std::string base =
      "[tunnel]\nshape = \"circular\"\nradius = 3.0\nlining_thickness = 0.3\n"
      "[materials.rock]\nyoung = 5e9\npoisson = 0.25\n"
      "[insitu]\nsigma_h = 1e6\nsigma_v = 1e6\n"
      "[materials.lining]\nyoung = 20e9\npoisson = 0.2\ncompressive_strength = 25e6\n"
      "tensile_strength = 2e6\n";
  const rw::Scene a = rw::parse_scene(base, "a.toml", ".");
  const rw::Scene b = rw::parse_scene(base + "section = \"plain\"\n", "b.toml", ".");
  const rw::LiningSectionSpec &sa = a.materials.at(rockfdem::mesh::kLining).section,
                              &sb = b.materials.at(rockfdem::mesh::kLining).section;
  EXPECT_EQ(sa.kind, "plain");
  EXPECT_EQ(sb.kind, "plain");
  EXPECT_EQ(sa.steel_young, sb.steel_young);
  const rw::LiningSection s = rw::lining_section(b.materials.at(rockfdem::mesh::kLining));
  EXPECT_EQ(s.kind, rw::SectionKind::kPlain);
  for (const rw::SectionForces& f :
       {rw::SectionForces{3e6, 0, 0}, {2e5, 3e4, 0}, {1e6, -1e4, 0}, {-1e5, 2e3, 0}})
    EXPECT_EQ(rw::section_safety_factor(f, 0.3, s), rw::safety_factor(f, 0.3, {25e6, 2e6}));
}

// A section's keys: each refused naming the key, its value and what is
// allowed.
TEST(LiningSectionKeys, bad_section_keys_are_refused) {
  const std::string base =
      "[tunnel]\nshape = \"circular\"\nradius = 3.0\nlining_thickness = 0.3\n"
      "[materials.rock]\nyoung = 5e9\npoisson = 0.25\n"
      "[insitu]\nsigma_h = 1e6\nsigma_v = 1e6\n"
      "[materials.lining]\nyoung = 20e9\npoisson = 0.2\n";
  const std::string fc = "compressive_strength = 30e6\n";
  const std::string bars = "section = \"reinforced\"\nsteel_yield_strength = 500e6\n";
  const auto refused = [&](const std::string& text, std::initializer_list<std::string> parts) {
    const std::string msg = error_of([&] { rw::parse_scene(base + text, "sec.toml", "."); });
    ASSERT_FALSE(msg.empty()) << text;
    for (const std::string& p : parts)
      EXPECT_NE(msg.find(p), std::string::npos) << p << ": " << msg;
  };
  refused(fc + "section = \"rebar\"\n",
          {"sec.toml", "materials.lining.section", "rebar", "\"reinforced\", \"steel_sets\""});
  refused(fc + bars + "bar_cover = 0.05\n",
          {"missing key 'materials.lining.bar_area'", "in (0, 0.1] (m^2)"});
  refused(bars + "bar_area = 1.131e-3\nbar_cover = 0.05\n",
          {"missing key 'materials.lining.compressive_strength'"});
  refused(fc + bars + "bar_area = 1.131e-3\nbar_cover = 0.15\n",
          {"sec.toml:18: key 'materials.lining.bar_cover' = 0.15", "allowed: < 0.15 m"});
  refused(fc + bars + "bar_area = 0.01\nbar_cover = 0.05\n",
          {"'materials.lining.bar_area' = 0.01", "4%", "allowed: <= 0.006 m^2/m"});
  refused(fc + bars + "bar_area = 1131\nbar_cover = 0.05\n",
          {"'materials.lining.bar_area' = 1131", "allowed: in (0, 0.1] (m^2)"});
  refused(fc + "set_area = 5.43e-3\n",
          {"materials.lining.set_area", "applies with section = \"steel_sets\"", "\"plain\""});
  refused(fc + "steel_yield_strength = 500e6\n",
          {"materials.lining.steel_yield_strength", "\"reinforced\" or \"steel_sets\""});
  const std::string sets =
      fc +
      "section = \"steel_sets\"\nsteel_yield_strength = 275e6\nset_area = 5.43e-3\n"
      "set_depth = 0.16\nset_spacing = 1.0\n";
  refused(sets, {"missing key 'materials.lining.set_inertia'"});
  refused(sets + "set_inertia = 2.492e-3\n",
          {"'materials.lining.set_inertia' = 0.002492", "allowed: <= 3.4752e-05 m^4"});
  refused(fc + "section = \"steel_sets\"\nsteel_yield_strength = 275e6\nset_area = 5.43e-3\n"
               "set_inertia = 2.492e-5\nset_depth = 0.4\nset_spacing = 1.0\n",
          {"'materials.lining.set_depth' = 0.4", "allowed: <= 0.3 m"});
  refused(fc + bars + "bar_area = 1.131e-3\nbar_cover = 0.05\nset_spacing = 1.0\n",
          {"materials.lining.set_spacing", "\"reinforced\""});
}

namespace {

struct CsvSegment {
  double y, thickness, thrust, moment, safety;
};

std::vector<CsvSegment> read_segments(const std::string& text) {
  std::vector<CsvSegment> out;
  for (const std::vector<double>& v : rockfdem::test::numeric_rows(text))
    out.push_back({v.at(5), v.at(6), v.at(7) * 1e3, v.at(8) * 1e3, v.at(11)});
  return out;
}

}  // namespace

// A run whose floor part is reinforced (lined_invert_horseshoe.toml's 0.4 m
// C40 invert with 2 x 1131 mm^2/m at 50 mm): every floor segment of
// lining.csv carries the reinforced diagram's factor of its own N, M and
// thickness, the rest the plain section's; the summary names both parts'
// sections and its smallest factor is the file's; report.md names them.
TEST(LiningSections, a_reinforced_invert_is_checked_with_its_diagram) {
  namespace fs = std::filesystem;
  namespace rt = rockfdem::test;
  const std::string scene = rt::kTestDir + "/lined_invert_horseshoe.toml";
  const std::string sets =
      " --set materials.invert.section=reinforced --set materials.invert.steel_yield_strength=500e6"
      " --set materials.invert.bar_area=1.131e-3 --set materials.invert.bar_cover=0.05";
  const fs::path out = rt::scratch("lining_sections_reinforced");
  const rt::Result r = rt::run("run " + scene + " -q -j 1" + sets + " -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const rw::Scene s = rw::load_scene(
      scene, {"materials.invert.section=reinforced", "materials.invert.steel_yield_strength=500e6",
              "materials.invert.bar_area=1.131e-3", "materials.invert.bar_cover=0.05"});
  const rw::LiningSection floor = rw::lining_section(*s.invert);
  const rw::LiningSection rest = rw::lining_section(s.materials.at(rockfdem::mesh::kLining));
  ASSERT_EQ(floor.kind, rw::SectionKind::kReinforced);
  double fs_min = INFINITY;
  int n_floor = 0;
  for (const CsvSegment& g : read_segments(rt::read_text(out / "lining.csv"))) {
    const bool in_floor = g.y < -2.1;  // the walls' feet: -2.5 + 0.4 m
    n_floor += in_floor;
    const double fs =
        rw::section_safety_factor({g.thrust, g.moment, 0}, g.thickness, in_floor ? floor : rest);
    EXPECT_NEAR(g.safety, fs, 1e-4 * fs) << g.y;
    fs_min = std::min(fs_min, g.safety);
  }
  EXPECT_GT(n_floor, 20);
  const nlohmann::json j = rt::read_json(out / "summary.json");
  const nlohmann::json& l = j["lining"];
  EXPECT_EQ(l["section"], "plain");
  EXPECT_EQ(l["invert_section"], "reinforced");
  EXPECT_NE(l["capacity"].get<std::string>().find("invert: reinforced section"), std::string::npos);
  EXPECT_NEAR(l["min_safety_factor"].get<double>(), fs_min, 1e-4 * fs_min);
  if (fs_min < 1 && l["min_safety_factor_in_invert"].get<bool>()) {
    EXPECT_NE(j["support"]["line"].get<std::string>().find("lining invert (reinforced) SF"),
              std::string::npos);
  }
  EXPECT_NE(rt::read_text(out / "report.md")
                .find("| section type | arch and walls plain; floor part reinforced |"),
            std::string::npos);
  fs::remove_all(out);
}
