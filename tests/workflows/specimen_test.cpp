// Specimen runs (UCS, Brazilian disc): checkpoints and restarts that end
// bit-identical to the uninterrupted run, the peak read every step, the
// post-peak stop and frictionless platens.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <thread>
#include <vector>

#include "cli_runner.hpp"
#include "rockfdem/mesh/build.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "run/checkpoint.hpp"
#include "run/engine_setup.hpp"
#include "stages/platen_load.hpp"

namespace fs = std::filesystem;
using namespace rockfdem::test;
using namespace rockfdem::workflows;

namespace {

// A small UCS (802 triangles) loaded past its peak: fracture and contact
// are active at every checkpoint after step 1400.
const std::string kScene =
    kTestDir + "/ucs_small.toml --set engine.steps=3000 --set output.every_steps=250 -q";

std::string hash_of(const fs::path& dir) {
  return read_json(dir / "summary.json")["state_hash"].get<std::string>();
}

// history.csv as numbers, by column name.
struct Table {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;
  double at(std::size_t row, const std::string& name) const {
    const auto k = std::find(names.begin(), names.end(), name) - names.begin();
    return rows[row][std::size_t(k)];
  }
};

Table read_history(const fs::path& dir) {
  std::istringstream in(read_text(dir / "history.csv"));
  Table t;
  std::string line, cell;
  std::getline(in, line);
  for (std::istringstream h(line); std::getline(h, cell, ',');) t.names.push_back(cell);
  while (std::getline(in, line)) {
    t.rows.emplace_back();
    for (std::istringstream r(line); std::getline(r, cell, ',');)
      t.rows.back().push_back(std::stod(cell));
  }
  return t;
}

// Frames listed in OUTDIR/fdem.pvd (written last at an output step).
std::size_t frames_listed(const fs::path& run_dir) {
  const std::string pvd = read_text(run_dir / "fdem.pvd");
  std::size_t n = 0;
  for (std::size_t at = pvd.find("<DataSet"); at != std::string::npos;
       at = pvd.find("<DataSet", at + 1))
    ++n;
  return n;
}

// SIGTERM `delay_ms` after the run has listed `frames` frames (its output
// step done, the next chunk of steps under way); returns the exit code.
int interrupt_after_frames(const std::string& args, const fs::path& out, std::size_t frames,
                           int delay_ms) {
  const pid_t pid = spawn(args, out.string() + ".log");
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (frames_listed(out) < frames && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
  kill(pid, SIGTERM);
  return wait_exit_code(pid);
}

}  // namespace

class SpecimenRestart : public ::testing::Test {
 protected:
  // The uninterrupted reference: 2 threads, a checkpoint every 500 steps
  // (the newest two, at 2000 and 2500, are kept), a frame every 250 steps.
  static void SetUpTestSuite() {
    ref_ = new fs::path(scratch("specimen-reference"));
    const Result r = run("run " + kScene + " -j 2 --checkpoint-every 500 -o " + ref_->string());
    ASSERT_EQ(r.code, 0) << r.output;
  }
  static void TearDownTestSuite() {
    fs::remove_all(*ref_);
    delete ref_;
  }
  static fs::path* ref_;
};
fs::path* SpecimenRestart::ref_ = nullptr;

// An output-step checkpoint (step 2000, past the peak, cracks broken and in
// contact) continues on 1 thread into another folder to the same state,
// history, frame series and peak.
TEST_F(SpecimenRestart, output_step_checkpoint_restarts_bit_identically) {
  const auto kept = checkpoints(*ref_);
  ASSERT_EQ(kept.size(), 2u) << "the newest two checkpoints are kept";
  ASSERT_EQ(checkpoint_step(kept[0]), 2000);
  const fs::path out = scratch("specimen-restart-j1");
  const Result r =
      run("run " + kScene + " -j 1 --restart " + kept[0].string() + " -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json a = read_json(*ref_ / "summary.json"), b = read_json(out / "summary.json");
  EXPECT_EQ(b["state_hash"], a["state_hash"]);
  EXPECT_GT(a["broken"]["mode_I"].get<long>() + a["broken"]["mode_II"].get<long>(), 0);
  EXPECT_EQ(b["specimen"], a["specimen"]) << "the peak found before step 2000 carries over";
  EXPECT_LT(a["specimen"]["peak_step"].get<long>(), 2000);
  EXPECT_EQ(b["restarted_from"]["step"].get<long>(), 2000);
  EXPECT_EQ(read_text(out / "history.csv"), read_text(*ref_ / "history.csv"));
  EXPECT_EQ(read_text(out / "fdem.pvd"), read_text(*ref_ / "fdem.pvd"));
  EXPECT_TRUE(fs::exists(out / "fdem_0000.vtu")) << "earlier frames come along";
  fs::remove_all(out);
}

// SIGTERM lands between output steps (every 250): the signal's checkpoint
// holds that step, and a restart on 2 threads in the same folder (as after
// the interruption) reaches the reference's state and history.
TEST_F(SpecimenRestart, signal_checkpoint_between_output_steps_restarts_bit_identically) {
  const fs::path out = scratch("specimen-sigterm");
  long at = 0;
  for (int attempt = 0; attempt < 5 && at % 250 == 0; ++attempt) {
    fs::remove_all(out);
    ASSERT_EQ(interrupt_after_frames("run " + kScene + " -j 1 -o " + out.string(), out, 3,
                                     10 + 15 * attempt),
              143)
        << read_text(out.string() + ".log");
    const auto kept = checkpoints(out);
    ASSERT_EQ(kept.size(), 1u) << "the signal's checkpoint alone";
    at = checkpoint_step(kept[0]);
  }
  ASSERT_NE(at % 250, 0) << "five signals all landed on output steps";
  EXPECT_EQ(read_json(out / "summary.json")["status"].get<std::string>(), "interrupted");
  const Result r = run("run " + kScene + " -j 2 --restart " + checkpoints(out)[0].string() +
                       " -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(hash_of(out), hash_of(*ref_));
  EXPECT_EQ(read_text(out / "history.csv"), read_text(*ref_ / "history.csv"))
      << "the interrupted run's extra row at step " << at << " is gone";
  EXPECT_EQ(read_json(out / "summary.json")["specimen"],
            read_json(*ref_ / "summary.json")["specimen"]);
  fs::remove_all(out);
  fs::remove(out.string() + ".log");
}

// A forged specimen run state (checksum recomputed) is refused with exit 2
// naming the checkpoint and the field; nothing is written.
TEST_F(SpecimenRestart, forged_run_state_is_refused_naming_the_field) {
  const fs::path dir = scratch("specimen-forged");
  const Scene scene =
      load_scene(kTestDir + "/ucs_small.toml", {"engine.steps=3000", "output.every_steps=250"});
  const Checkpoint good = read_checkpoint(checkpoints(*ref_).back().string(), scene);
  nlohmann::json state = good.run;
  state["outputs"]["load"].erase("peak_stress");
  const std::string forged = write_checkpoint(dir.string(), 1, scene, {state, good.engine_state});
  const fs::path out = dir / "out";
  const Result r = run("run " + kScene + " --restart " + forged + " -o " + out.string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("checkpoint " + forged +
                          ": corrupt run state: field 'outputs.load.peak_stress' is missing"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(out)) << "nothing written";
  fs::remove_all(dir);
}

// ---- The peak, read every step ----------------------------------------------
// A fast platen (4 m/s, strain rate 80 /s) takes the small UCS past its
// peak within 500 steps. The peak used to be the largest output row.
namespace {

const std::string kFast = kTestDir +
                          "/ucs_small.toml -q -j 1 --set loading.platen_velocity=4"
                          " --set engine.steps=3000 --set output.vtk=false"
                          " --set loading.stop_after_peak=0.7";

}  // namespace

TEST(SpecimenPeak, is_the_largest_platen_stress_of_every_step_and_stops_after_it) {
  // Independent: a row at every step, its largest stress read from history.csv.
  const fs::path every = scratch("specimen-peak-every");
  ASSERT_EQ(run("run " + kFast + " --set output.every_steps=1 -o " + every.string()).code, 0);
  const Table t = read_history(every);
  std::size_t top = 0;
  for (std::size_t i = 0; i < t.rows.size(); ++i)
    if (t.at(i, "axial_stress") > t.at(top, "axial_stress")) top = i;
  const nlohmann::json peak = read_json(every / "summary.json")["specimen"];
  // history.csv prints 10 significant digits.
  EXPECT_NEAR(peak["peak_stress"].get<double>(), t.at(top, "axial_stress"),
              1e-9 * t.at(top, "axial_stress"));
  EXPECT_EQ(peak["peak_step"].get<double>(), t.at(top, "step"));
  EXPECT_NEAR(peak["peak_strain"].get<double>(), t.at(top, "axial_strain"),
              1e-9 * t.at(top, "axial_strain"));
  // The pre-peak modulus: the least-squares slope of every step's stress
  // against its strain up to the peak, over 0.2-0.6 of the peak (all steps
  // are kept below 2048: no decimation).
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double p = t.at(top, "axial_stress");
  for (std::size_t i = 0; i <= top; ++i) {
    const double x = t.at(i, "axial_strain"), y = t.at(i, "axial_stress");
    if (y < 0.2 * p || y > 0.6 * p) continue;
    n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  ASSERT_GE(n, 5);
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  EXPECT_NEAR(peak["modulus"].get<double>(), slope, 1e-6 * slope);
  // The stop: the first step after which the stress is at most 0.7 of the
  // peak so far with a crack element broken; the run's last row.
  const std::size_t last = t.rows.size() - 1;
  double so_far = 0;
  for (std::size_t i = 0; i < last; ++i) {
    so_far = std::max(so_far, t.at(i, "axial_stress"));
    const double broken = t.at(i, "broken_I") + t.at(i, "broken_II") + t.at(i, "broken_mixed");
    EXPECT_FALSE(broken > 0 && t.at(i, "axial_stress") <= 0.7 * so_far) << "row " << i;
  }
  EXPECT_LE(t.at(last, "axial_stress"), 0.7 * t.at(top, "axial_stress"));
  EXPECT_GT(t.at(last, "broken_I") + t.at(last, "broken_II") + t.at(last, "broken_mixed"), 0);
  EXPECT_EQ(peak["stopped_after_peak_at_step"].get<double>(), t.at(last, "step"));
  EXPECT_LT(t.at(last, "step"), 3000);

  // Rows every 100 steps: the same run, the same peak, at least every row.
  const fs::path sparse = scratch("specimen-peak-sparse");
  ASSERT_EQ(run("run " + kFast + " --set output.every_steps=100 -o " + sparse.string()).code, 0);
  EXPECT_EQ(hash_of(sparse), hash_of(every));
  EXPECT_EQ(read_json(sparse / "summary.json")["specimen"], peak);
  ASSERT_NE(long(t.at(top, "step")) % 100, 0) << "the peak falls between rows here";
  const Table s = read_history(sparse);
  for (std::size_t i = 0; i < s.rows.size(); ++i)
    EXPECT_LT(s.at(i, "axial_stress"), peak["peak_stress"].get<double>()) << "row " << i;
  fs::remove_all(every);
  fs::remove_all(sparse);
}

// ---- Platens -----------------------------------------------------------------
// The small UCS loaded slowly (0.02 m/s per platen, local damping 0.5) to
// an axial strain of 9e-5, elastic (no crack element breaks).
namespace {

struct Lateral {
  double corner;          ///< x displacement of the right end's corners (mean) [m]
  double mid;             ///< x displacement of the right side at mid-height [m]
  double lateral_strain;  ///< (u right - u left) / width at mid-height [-]
  double axial_strain;    ///< 2 v t / height [-]
  double stress;          ///< mean axial stress on the upper platen [Pa]
  double closed_form;     ///< lateral strain of a uniform uniaxial stress `stress` [-]
  long broken;
};

Lateral load_elastically(const std::string& friction) {
  const Scene s = load_scene(kTestDir + "/ucs_small.toml",
                             {"loading.platen_friction=" + friction, "loading.platen_velocity=0.02",
                              "engine.local_damping=0.5"});
  const rockfdem::mesh::Mesh m = rockfdem::mesh::build_mesh(s.mesh);
  rockfdem::fdem::Engine e = make_engine(specimen_model_input(s, m, 1), s, false);
  for (int i = 0; i < 3000; ++i) e.step();
  const double w = s.mesh.specimen.width, h = s.mesh.specimen.height;
  const double x0 = *std::min_element(m.x.begin(), m.x.end());
  const double y0 = *std::min_element(m.y.begin(), m.y.end());
  // Nodes on the sides: the one nearest mid-height, and the end corners.
  double best_right = h, best_left = h, corner_sum = 0;
  Lateral r{};
  double left = 0;
  int corners = 0;
  for (std::size_t n = 0; n < e.n_nodes(); ++n) {
    const int v = e.node_vertex()[n];
    const double x = m.x[std::size_t(v)] - x0, y = m.y[std::size_t(v)] - y0;
    const double ux = e.displacement(n)[0], off = std::abs(y - h / 2);
    if (std::abs(x - w) < 1e-9 && (y < 1e-9 || y > h - 1e-9)) corner_sum += ux, ++corners;
    if (std::abs(x - w) < 1e-9 && off < best_right) best_right = off, r.mid = ux;
    if (std::abs(x) < 1e-9 && off < best_left) best_left = off, left = ux;
  }
  r.corner = corner_sum / corners;
  r.lateral_strain = (r.mid - left) / w;
  r.axial_strain = 2 * s.engine.platen_velocity * e.time() / h;
  r.stress = PlatenLoad(s).read(e).stress;
  r.broken = e.broken_counts().total();
  // Plane strain under a uniform axial stress alone: eps_xx = -nu (1 + nu) / E sigma_yy.
  const auto& rock = s.materials.at(rockfdem::mesh::kRock);
  r.closed_form = rock.poisson * (1 + rock.poisson) / rock.young * r.stress;
  return r;
}

}  // namespace

TEST(SpecimenPlatens, rough_ones_hold_the_ends_frictionless_ones_let_them_spread) {
  const Lateral rough = load_elastically("rough");
  const Lateral free = load_elastically("frictionless");
  EXPECT_EQ(rough.broken + free.broken, 0) << "elastic";
  EXPECT_EQ(rough.corner, 0.0) << "rough platens hold the ends";
  // Frictionless: the ends spread as far as mid-height (measured 1.6% more)
  // and the lateral strain is the uniform uniaxial state's (measured 2.6%
  // below it: the platen's stress leads the mid-height's while loading).
  EXPECT_GT(free.corner, 0.0);
  EXPECT_NEAR(free.corner, free.mid, 0.05 * free.mid);
  EXPECT_NEAR(free.lateral_strain, free.closed_form, 0.05 * free.closed_form);
}
