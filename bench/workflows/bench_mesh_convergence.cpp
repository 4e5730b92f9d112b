// Mesh convergence: run time against error for a tunnel scene. The scene is
// run once per near-field element size h (mesh.size_near) by the rockfdem
// binary itself, and the key-point displacements are compared across h.
//
//   build/bench/workflows/bench_mesh_convergence [--scene scenes/tunnel-seed.toml]
//       [--sizes 0.5,0.35,0.25,0.175] [--threads 2] [--out /tmp/rockfdem-convergence]
//       [--rockfdem build/bin/rockfdem] [--set section.key=value ...] [--reuse]
//
// Each size is one run
//
//   rockfdem run SCENE -q -j THREADS -o OUT/h_<size> --force
//       --set mesh.size_near=<size> --set output.vtk=false --set output.plots=false [--set ...]
//
// with its console output in OUT/h_<size>.log. The program then reads each
// run's summary.json and prints, as Markdown to paste into docs/benchmarks.md:
//
//   1. one row per size: h / l_ch, triangles, steps, wall time, status, |u| at
//      the five key points, broken-zone depth, broken crack counts, and the
//      difference of vault, shoulders (mean) and walls (mean) from the finest run;
//   2. a Richardson extrapolation from the finest three sizes, where their
//      refinement ratios are (nearly) constant: observed order p, the
//      extrapolated value f* and each run's error against f*.
//
// The figures are those of the FDEM answer at the end of the last stage, so
// "error" here is discretisation error plus whatever the stopping criteria
// leave; a run that is not at equilibrium says so in its status.
//
//         |u| [mm]
//          |  x h = 0.5
//          |      x 0.35
//          |         x 0.25
//          |           x 0.175
//          | - - - - - - - - - - f* (h -> 0)
//          +--------------------------------- wall time [s]
//
// --reuse keeps a size whose OUT/h_<size>/summary.json has a terminal status
// (completed, not_at_equilibrium, unstable) and was made by the same rockfdem
// command (OUT/h_<size>.cmd), so a long study can be stopped and resumed.
// Exit code: 0 when every run exited 0, 1 when one did not, 2 for bad options;
// an interrupted run (Ctrl-C) stops the study after printing what there is.
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_process.hpp"

namespace fs = std::filesystem;
using bench::fixed;
using bench::join_quoted;
using bench::last_line;
using bench::number_at;
using bench::read_text;
using bench::size_text;
using bench::UsageError;
using nlohmann::json;

namespace {

const char* const kUsage =
    "usage: bench_mesh_convergence [--scene PATH] [--sizes H1,H2,...] [--threads N]\n"
    "                              [--out DIR] [--rockfdem PATH] [--set KEY=VALUE ...] [--reuse]\n";

struct Options {
  std::string scene = std::string(ROCKFDEM_SOURCE_DIR) + "/scenes/tunnel-seed.toml";
  std::vector<double> sizes{0.5, 0.35, 0.25, 0.175};
  int threads = 2;
  std::string out = "/tmp/rockfdem-convergence";
  std::string rockfdem = ROCKFDEM_BINARY;
  std::vector<std::string> sets;
  bool reuse = false;
  std::string command_line;  // as typed, for the header
};

// ---------------------------------------------------------------- helpers

std::string percent(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%+.1f%%", 100 * v);
  return buf;
}

std::string text_or_dash(const std::optional<double>& v, int decimals) {
  return v ? fixed(*v, decimals) : "-";
}

std::optional<double> mean(const std::optional<double>& a, const std::optional<double>& b) {
  if (!a || !b) return std::nullopt;
  return (*a + *b) / 2;
}

bool is_terminal(const std::string& status) {
  return status == "completed" || status == "not_at_equilibrium" || status == "unstable";
}

std::vector<double> parse_sizes(const std::string& list) {
  std::vector<double> sizes;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');) {
    char* end = nullptr;
    const double h = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !(h > 0) || !std::isfinite(h))
      throw UsageError("--sizes " + list + ": '" + item +
                       "' is not a positive number; give sizes in metres, e.g. 0.5,0.35,0.25");
    sizes.push_back(h);
  }
  // Coarse to fine, each size once: the table reads down towards h -> 0.
  std::sort(sizes.begin(), sizes.end(), std::greater<double>());
  sizes.erase(std::unique(sizes.begin(), sizes.end(),
                          [](double a, double b) { return size_text(a) == size_text(b); }),
              sizes.end());
  return sizes;
}

Options parse_options(int argc, char** argv) {
  Options o;
  std::vector<std::string> words(argv, argv + argc);
  o.command_line = join_quoted(words);
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError(a + " needs a value");
      return argv[++i];
    };
    if (a == "--scene") {
      o.scene = value();
    } else if (a == "--sizes") {
      o.sizes = parse_sizes(value());
    } else if (a == "--threads") {
      const std::string v = value();
      char* end = nullptr;
      const long n = std::strtol(v.c_str(), &end, 10);
      if (v.empty() || *end != '\0' || n < 1 || n > 1024)
        throw UsageError("--threads " + v + ": expected a whole number of threads >= 1");
      o.threads = int(n);
    } else if (a == "--out") {
      o.out = value();
    } else if (a == "--rockfdem") {
      o.rockfdem = value();
    } else if (a == "--set") {
      o.sets.push_back(value());
    } else if (a == "--reuse") {
      o.reuse = true;
    } else if (a == "-h" || a == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else {
      throw UsageError("unknown option '" + a + "'");
    }
  }
  if (o.sizes.empty()) throw UsageError("--sizes: give at least one size");
  if (access(o.rockfdem.c_str(), X_OK) != 0)
    throw UsageError("rockfdem binary '" + o.rockfdem +
                     "' is not executable; build it (cmake --build build --target rockfdem) "
                     "or pass --rockfdem PATH");
  if (!fs::is_regular_file(o.scene))
    throw UsageError("scene '" + o.scene + "' not found; pass --scene PATH");
  return o;
}

// ---------------------------------------------------------------- the study

// One size's run and the figures its summary.json gave.
struct Row {
  double size = 0;
  bool reused = false;
  int exit_code = 0;  // of rockfdem; 0 for a reused run
  bool have_summary = false;
  std::string status;  // summary's status, "" when none
  std::optional<double> h_over_l_ch, triangles, steps, wall_s, depth_m;
  std::optional<double> vault, left_shoulder, right_shoulder, left_wall, right_wall;
  std::optional<double> mode_I, mode_II, mixed;

  std::optional<double> shoulders() const { return mean(left_shoulder, right_shoulder); }
  std::optional<double> walls() const { return mean(left_wall, right_wall); }
  std::optional<double> broken_total() const {
    if (!mode_I || !mode_II || !mixed) return std::nullopt;
    return *mode_I + *mode_II + *mixed;
  }
  // Figures worth comparing: the run ended at equilibrium or at its step limit.
  bool usable() const {
    return have_summary && (status == "completed" || status == "not_at_equilibrium");
  }
};

// The three quantities compared across sizes.
struct Quantity {
  const char* name;
  std::optional<double> (*of)(const Row&);
};
const Quantity kQuantities[] = {
    {"vault [mm]", [](const Row& r) { return r.vault; }},
    {"shoulders, mean [mm]", [](const Row& r) { return r.shoulders(); }},
    {"walls, mean [mm]", [](const Row& r) { return r.walls(); }},
};

class ConvergenceStudy {
 public:
  explicit ConvergenceStudy(Options options) : o_(std::move(options)) {}

  int run() {
    // 1. Run (or reuse) each size, coarse to fine, so that the cheap answers
    //    come first and an interrupted study still has a table.
    fs::create_directories(o_.out);
    for (double h : o_.sizes) {
      rows_.push_back(run_size(h));
      if (rows_.back().exit_code == 130 || rows_.back().exit_code == 143) {
        std::cerr << "interrupted: the table below stops at h = " << size_text(h) << '\n';
        break;
      }
    }
    // 2. The report: header, one row per size, the extrapolation.
    print_header();
    print_table();
    print_extrapolation();
    for (const Row& r : rows_)
      if (r.exit_code != 0) return 1;
    return 0;
  }

 private:
  std::vector<std::string> rockfdem_args(double h) const {
    std::vector<std::string> a = {o_.rockfdem,
                                  "run",
                                  o_.scene,
                                  "-q",
                                  "-j",
                                  std::to_string(o_.threads),
                                  "-o",
                                  (fs::path(o_.out) / ("h_" + size_text(h))).string(),
                                  "--force",
                                  "--set",
                                  "mesh.size_near=" + size_text(h),
                                  "--set",
                                  "output.vtk=false",
                                  "--set",
                                  "output.plots=false"};
    for (const std::string& s : o_.sets) {
      a.push_back("--set");
      a.push_back(s);
    }
    return a;
  }

  fs::path log_path(double h) const { return fs::path(o_.out) / ("h_" + size_text(h) + ".log"); }

  Row run_size(double h) const {
    Row row;
    row.size = h;
    const std::string name = "h_" + size_text(h);
    const fs::path summary = fs::path(o_.out) / name / "summary.json";
    const fs::path stamp = fs::path(o_.out) / (name + ".cmd");
    const fs::path log = log_path(h);
    const std::vector<std::string> args = rockfdem_args(h);
    const std::string command = join_quoted(args);

    if (o_.reuse && fs::exists(summary)) {
      read_summary(summary, row);
      const bool same_command = fs::exists(stamp) && read_text(stamp) == command + "\n";
      if (is_terminal(row.status) && same_command) {
        row.reused = true;
        std::cerr << "h = " << name.substr(2) << ": reusing " << summary.string() << " ("
                  << row.status << ")\n";
        return row;
      }
      std::cerr << "h = " << name.substr(2) << ": not reusing " << summary.string() << " ("
                << (same_command ? "status '" + row.status + "' is not terminal"
                                 : "no " + stamp.string() + " with this command")
                << ")\n";
      row = Row{};
      row.size = h;
    }
    std::cerr << "h = " << name.substr(2) << ": " << command << " > " << log.string() << '\n';
    std::ofstream(stamp) << command << '\n';  // closed at the end of the statement
    // A stale summary must not pass for this run's.
    std::error_code ignored;
    fs::remove(summary, ignored);
    row.exit_code = bench::run_logged(args, log.string()).exit_code;
    if (fs::exists(summary)) read_summary(summary, row);
    std::cerr << "h = " << name.substr(2) << ": exit " << row.exit_code
              << (row.status.empty() ? "" : ", " + row.status) << '\n';
    return row;
  }

  static void read_summary(const fs::path& path, Row& row) {
    json j;
    try {
      j = json::parse(read_text(path));
    } catch (const json::exception& e) {
      std::cerr << path.string() << ": unreadable (" << e.what() << ")\n";
      return;
    }
    row.have_summary = true;
    if (j.contains("status") && j["status"].is_string()) row.status = j["status"];
    row.h_over_l_ch = number_at(j, {"resolution", "h_over_l_ch"});
    row.triangles = number_at(j, {"counts", "triangles"});
    row.steps = number_at(j, {"steps"});
    row.wall_s = number_at(j, {"timings", "total"});
    row.depth_m = number_at(j, {"broken_zone", "depth_m"});
    const auto u = [&](const char* point) -> std::optional<double> {
      const auto v = number_at(j, {"monitors", point, "u_mm"});
      return v ? std::optional<double>(std::abs(*v)) : std::nullopt;
    };
    row.vault = u("vault");
    row.left_shoulder = u("left_shoulder");
    row.right_shoulder = u("right_shoulder");
    row.left_wall = u("left_wall");
    row.right_wall = u("right_wall");
    row.mode_I = number_at(j, {"broken", "mode_I"});
    row.mode_II = number_at(j, {"broken", "mode_II"});
    row.mixed = number_at(j, {"broken", "mixed"});
  }

  // The finest run whose figures can serve as a reference, or null.
  const Row* finest_usable() const {
    for (auto it = rows_.rbegin(); it != rows_.rend(); ++it)
      if (it->usable()) return &*it;
    return nullptr;
  }

  void print_header() const {
    const bench::Machine machine = bench::this_machine();
    std::vector<std::string> each = rockfdem_args(0);
    each[7] = (fs::path(o_.out) / "h_<size>").string();
    each[10] = "mesh.size_near=<size>";
    std::cout << "## Mesh convergence: " << fs::path(o_.scene).filename().string() << "\n\n"
              << "    " << o_.command_line << "\n\n"
              << machine.date << ", " << machine.host << ", " << machine.cpus << " cores (nproc), "
              << o_.threads << (o_.threads == 1 ? " thread" : " threads")
              << " per run. Each size ran as\n\n"
              << "    " << join_quoted(each) << "\n\n";
  }

  void print_table() const {
    std::cout << "| size_near h [m] | h / l_ch | triangles | steps | wall [s] | status "
                 "| vault [mm] | l. shoulder [mm] | r. shoulder [mm] | l. wall [mm] "
                 "| r. wall [mm] | broken zone [m] | broken I | II | mixed | total "
                 "| vault vs finest | shoulders vs finest | walls vs finest |\n"
              << "|---:|---:|---:|---:|---:|:---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
                 "---:|---:|---:|---:|\n";
    const Row* ref = finest_usable();
    for (const Row& r : rows_) {
      std::string status = r.status.empty() ? (r.have_summary ? "-" : "no summary.json") : r.status;
      if (r.exit_code != 0) status += " (exit " + std::to_string(r.exit_code) + ")";
      if (r.reused) status += " (reused)";
      std::cout << "| " << size_text(r.size) << " | " << text_or_dash(r.h_over_l_ch, 2) << " | "
                << text_or_dash(r.triangles, 0) << " | " << text_or_dash(r.steps, 0) << " | "
                << text_or_dash(r.wall_s, r.wall_s && *r.wall_s < 10 ? 2 : 1) << " | " << status
                << " | " << text_or_dash(r.vault, 2) << " | " << text_or_dash(r.left_shoulder, 2)
                << " | " << text_or_dash(r.right_shoulder, 2) << " | "
                << text_or_dash(r.left_wall, 2) << " | " << text_or_dash(r.right_wall, 2) << " | "
                << text_or_dash(r.depth_m, 2) << " | " << text_or_dash(r.mode_I, 0) << " | "
                << text_or_dash(r.mode_II, 0) << " | " << text_or_dash(r.mixed, 0) << " | "
                << text_or_dash(r.broken_total(), 0);
      for (const Quantity& q : kQuantities) {
        std::cout << " | ";
        if (&r == ref) {
          std::cout << "ref";
          continue;
        }
        const auto f = q.of(r);
        const auto f_ref = ref ? q.of(*ref) : std::nullopt;
        std::cout << (f && f_ref && *f_ref != 0 ? percent((*f - *f_ref) / std::abs(*f_ref)) : "-");
      }
      std::cout << " |\n";
    }
    std::cout << '\n';
    for (const Row& r : rows_)
      if (r.exit_code != 0)
        std::cout << "h = " << size_text(r.size) << " exited " << r.exit_code << ": "
                  << last_line(log_path(r.size)) << "\n\n";
    std::cout << "Displacements are |u| at the key points (`monitors.*.u_mm`); wall time is "
                 "`timings.total`.\n";
    if (ref)
      std::cout << "Differences are (f - f_ref) / f_ref against the finest run that completed or "
                   "stopped at its step limit (h = "
                << size_text(ref->size) << ", " << ref->status << ").\n\n";
    else
      std::cout << "No run completed: no differences.\n\n";
  }

  // Observed order for the three finest usable sizes h1 < h2 < h3 (f1 finest).
  // With a constant ratio r = h2/h1 = h3/h2 this is p = ln((f3-f2)/(f2-f1)) / ln r;
  // where the two ratios differ slightly (0.35/0.25 = 1.4, 0.25/0.175 = 1.43)
  // p solves the general form (Celik et al. 2008, J. Fluids Eng. 130, 078001)
  //   p = [ln((f3-f2)/(f2-f1)) + ln((r21^p - 1)/(r32^p - 1))] / ln r21
  // by fixed-point iteration from the constant-ratio value; the extrapolation
  // is then f* = f1 + (f1 - f2) / (r21^p - 1).
  static std::optional<double> observed_order(double ratio, double r21, double r32) {
    const auto q = [&](double p) {
      if (std::abs(p) < 1e-9) return std::log(std::log(r21) / std::log(r32));  // the p -> 0 limit
      return std::log((std::pow(r21, p) - 1) / (std::pow(r32, p) - 1));
    };
    double p = std::log(ratio) / std::log(r21);
    for (int it = 0; it < 100; ++it) {
      const double next = (std::log(ratio) + q(p)) / std::log(r21);
      if (!std::isfinite(next)) return std::nullopt;
      if (std::abs(next - p) < 1e-12 * (1 + std::abs(p))) return next;
      p = next;
    }
    return std::nullopt;
  }

  void print_extrapolation() const {
    std::vector<const Row*> use;
    for (auto it = rows_.rbegin(); it != rows_.rend() && use.size() < 3; ++it)
      if (it->usable()) use.push_back(&*it);
    if (use.size() < 3) {
      std::cout << "Richardson extrapolation: needs three sizes that completed or stopped at "
                   "their step limit; have "
                << use.size() << ".\n";
      return;
    }
    const Row &r1 = *use[0], &r2 = *use[1], &r3 = *use[2];
    const double r21 = r2.size / r1.size, r32 = r3.size / r2.size;
    std::cout << "### Richardson extrapolation, h = " << size_text(r3.size) << ", "
              << size_text(r2.size) << ", " << size_text(r1.size) << " (r = " << fixed(r32, 3)
              << ", " << fixed(r21, 3) << ")\n\n";
    if (std::abs(r21 / r32 - 1) > 0.05) {
      std::cout << "The refinement ratios differ by more than 5%: no extrapolation; choose "
                   "sizes with a constant ratio, e.g. 0.5,0.35,0.25,0.175.\n";
      return;
    }
    std::cout << "| quantity | (f3-f2)/(f2-f1) | order p | f* |";
    for (const Row& r : rows_) std::cout << " h = " << size_text(r.size) << " vs f* |";
    std::cout << "\n|:---|---:|---:|---:|";
    for (std::size_t i = 0; i < rows_.size(); ++i) std::cout << "---:|";
    std::cout << '\n';
    for (const Quantity& q : kQuantities) {
      std::cout << "| " << q.name << " | ";
      const auto f1 = q.of(r1), f2 = q.of(r2), f3 = q.of(r3);
      std::optional<double> f_star;
      if (!f1 || !f2 || !f3) {
        std::cout << "- | - | - |";
      } else if (*f2 == *f1) {
        std::cout << "- | f2 = f1: no order | - |";
      } else {
        const double ratio = (*f3 - *f2) / (*f2 - *f1);
        std::cout << fixed(ratio, 3) << " | ";
        const auto p = ratio > 0 ? observed_order(ratio, r21, r32) : std::nullopt;
        if (ratio <= 0) {
          std::cout << "no monotone convergence | - |";
        } else if (!p) {
          std::cout << "no order found | - |";
        } else if (*p <= 0) {
          std::cout << fixed(*p, 2) << " (differences grow) | - |";
        } else {
          f_star = *f1 + (*f1 - *f2) / (std::pow(r21, *p) - 1);
          std::cout << fixed(*p, 2) << " | " << fixed(*f_star, 2) << " |";
        }
      }
      for (const Row& r : rows_) {
        const auto f = q.of(r);
        std::cout << ' '
                  << (f && f_star && *f_star != 0 ? percent((*f - *f_star) / std::abs(*f_star))
                                                  : "-")
                  << " |";
      }
      std::cout << '\n';
    }
    std::cout << "\nf1 is the finest of the three, r = h3/h2, h2/h1; p from (f3-f2)/(f2-f1) "
                 "and both ratios; f* = f1 + (f1-f2)/(r^p - 1) with r = h2/h1; errors are "
                 "(f - f*) / f*.\n";
  }

  const Options o_;
  std::vector<Row> rows_;
};

}  // namespace

int main(int argc, char** argv) {
  try {
    ConvergenceStudy study(parse_options(argc, argv));
    return study.run();
  } catch (const UsageError& e) {
    std::cerr << "bench_mesh_convergence: " << e.what() << '\n' << kUsage;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "bench_mesh_convergence: " << e.what() << '\n';
    return 1;
  }
}
