// Gravity in tunnel runs (scene_build.cpp relate_gravity, the engine's
// weight of softened triangles): an unexcavated box under its own weight
// stays still, and an elastic tunnel excavated under gravity matches the
// closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.hpp"

namespace fs = std::filesystem;
using rockfdem::test::kTestDir;
using rockfdem::test::read_json;
using rockfdem::test::read_text;
using rockfdem::test::Result;
using rockfdem::test::run;
using rockfdem::test::scratch;

namespace {

const std::string kScene = kTestDir + "/gravity_circular.toml";

// The monitors' largest displacement component [mm].
double largest_monitor_mm(const nlohmann::json& monitors) {
  double m = 0;
  for (const auto& [name, point] : monitors.items())
    if (point.is_object() && point.contains("ux_mm"))
      m = std::max(
          {m, std::fabs(point["ux_mm"].get<double>()), std::fabs(point["uy_mm"].get<double>())});
  return m;
}

}  // namespace

// The box, its core in place (alpha 1), 100 m deep in rock of unit weight
// rho g = 24.5 kPa/m, with crack elements within 2 m of the opening, run for
// 2000 explicit steps with the criteria set out of reach: every key point
// moves less than 1e-6 mm (measured 3e-14 mm over 6000 steps).
// The in-situ field grows with depth as the weight asks and the rollers
// carry the sides, so nothing is out of balance; without the gradient
// (engine gravity alone) the box would sag by about rho g H^2 / (2 E) =
// 25 mm, and without the weight (the gradient alone) as much upwards.
TEST(Gravity, an_unexcavated_box_under_its_weight_stays_still) {
  const fs::path dir = scratch("gravity-box");
  fs::create_directories(dir);
  std::string text = read_text(kScene);
  text.replace(text.find("alpha = [1.0, 0.2]"), 18, "alpha = [1.0]");
  const std::string removal = "[[stages]]\nkind = \"remove_core\"\nmax_steps = 0\n\n";
  text.erase(text.find(removal), removal.size());
  text.replace(text.find("ratio = 1e-5"), 12, "ratio = 1e-30");
  text.replace(text.find("max_steps = 20000"), 17, "max_steps = 2000");
  text.replace(text.find("radius = 3.0"), 12, "radius = 3.0\nfracture_zone = 2.0");
  std::ofstream(dir / "box.toml") << text;
  const fs::path out = dir / "out";
  const Result r = run("run " + (dir / "box.toml").string() + " -q -j 2 -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json j = read_json(out / "summary.json");
  EXPECT_EQ(j["status"], "not_at_equilibrium");  // ratio 1e-30: it ran all its steps
  EXPECT_GE(j["steps"].get<long>(), 2000);
  const double moved = largest_monitor_mm(j["monitors"]);
  std::printf("unexcavated box under gravity: largest key-point displacement %.3g mm\n", moved);
  EXPECT_LT(moved, 1e-6);
  EXPECT_EQ(j["broken"]["mode_I"].get<long>() + j["broken"]["mode_II"].get<long>() +
                j["broken"]["mixed"].get<long>(),
            0);
  fs::remove_all(dir);
}

// An elastic circular tunnel (a = 3 m) excavated under gravity: sV = 1.5
// MPa and sH = 2.25 MPa at the axis, growing by gamma = 24.5 kPa/m with
// depth (5% of sV across the radius). By superposition the field is the
// uniform one at the axis plus a part odd in y (the gradient and the
// weight); the odd part moves the crown and the invert by the same uy and
// the walls not at all in x, so both chords are Kirsch's with the axis
// stresses (2%; the box and mesh account for about 1%):
//   crown-invert: 2 (a / 4G) [(sH + sV) - (sH - sV)(3 - 4 nu)],
//   wall-wall:    2 (a / 4G) [(sH + sV) + (sH - sV)(3 - 4 nu)].
// The odd part shows in the stresses, which stay within 1% of the implicit
// open hole solved with the same weight (relative L2 over a <= r <= 5a;
// measured 0.4%). Without the engine's weight (the gradient alone) the
// chords are the same but the stresses miss by 6.8%, and the box of the
// test above moves by 0.56 mm: both measured, both fail.
TEST(Gravity, elastic_tunnel_chords_match_kirsch_at_the_axis_stresses) {
  const fs::path out = scratch("gravity-tunnel");
  const Result r = run("run " + kScene + " -q -j 2 -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json j = read_json(out / "summary.json");
  EXPECT_EQ(j["status"], "completed");
  const double a = 3.0, E = 5e9, nu = 0.25, G = E / (2 * (1 + nu)), sH = 2.25e6, sV = 1.5e6;
  const double vertical = 2 * a / (4 * G) * ((sH + sV) - (sH - sV) * (3 - 4 * nu));
  const double wall = 2 * a / (4 * G) * ((sH + sV) + (sH - sV) * (3 - 4 * nu));
  const nlohmann::json& m = j["monitors"];
  const double chord_v = m["invert"]["uy_mm"].get<double>() - m["vault"]["uy_mm"].get<double>();
  const double chord_w = m["wall_chord_convergence_mm"].get<double>();
  std::printf("gravity tunnel: vertical chord %.4f mm (Kirsch %.4f), walls %.4f mm (%.4f)\n",
              chord_v, 1000 * vertical, chord_w, 1000 * wall);
  EXPECT_NEAR(chord_v, 1000 * vertical, 0.02 * 1000 * vertical);
  EXPECT_NEAR(chord_w, 1000 * wall, 0.02 * 1000 * wall);
  const double l2 = j["comparison"]["fdem_vs_insitu_rel_l2"].get<double>();
  std::printf("gravity tunnel: FDEM against the implicit open hole, rel. L2 %.4f\n", l2);
  EXPECT_LT(l2, 0.01);
  fs::remove_all(out);
}
