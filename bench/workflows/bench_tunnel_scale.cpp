// The seed tunnel at scale, end to end: meshing, the implicit stage and a
// fixed number of explicit steps, with the time and the peak memory of each
// phase, and the engine's UCS bench at the same triangle count and thread
// count in the same run, so that the tunnel's explicit throughput is compared
// like for like with the bench's.
//
//   build/bench/workflows/bench_tunnel_scale [--scene scenes/tunnel-seed-oneshot.toml]
//       [--sizes 0.35,0.06] [--threads 1,2] [--steps 10000] [--ucs-steps N]
//       [--ucs-repeats 3] [--out /tmp/rockfdem-scale] [--rockfdem PATH] [--bench-ucs PATH]
//       [--set section.key=value ...]
//
// Each size and thread count is one run of the rockfdem binary
//
//   rockfdem run SCENE -q -j T -o OUT/h_<size>_t<T> --force
//       --set mesh.size_near=<size> --set output.vtk=false --set output.plots=false
//       --set stages[5].max_steps=<steps> --set stages[5].ratio=1e-9 [--set ...]
//
// (stages[5] is the one-shot seed scene's equilibrium stage: the tiny ratio keeps it
// stepping to its cap, so every size runs about the same number of explicit
// steps: those of the grout stage before it, which ends when its trigger
// fires, plus <steps>; the table gives the steps taken). Then
// `bench_ucs --triangles <the tunnel's>
// --steps <ucs-steps> --threads T --contact 1`, <ucs-repeats> times in a row:
// its median rate is the ratio's denominator, and its spread is printed
// (a bench of a few seconds moves with the machine by tens of percent).
// Printed as Markdown:
//
//   1. per run: triangles, steps, status, wall time of each phase of the run
//      (summary.json "timings"), the process's peak resident memory and per
//      triangle, the engine's own bytes per triangle, the tunnel's explicit
//      triangle-steps/s, the bench's median at the same size, its lowest
//      and highest, and the ratio to the median; a line under the table
//      where the repeats lie more than 20% apart (the ratio not settled);
//   2. per run: each engine module's time per element-step in the tunnel
//      (summary.json "fdem_modules" and "counts") and in the bench's median
//      repeat (its "phases" line and counts), and the modules both run
//      (triangles, crack elements, nodes) priced at the bench's rates over
//      the tunnel's counts against the tunnel's own time: the like-for-like
//      comparison, since the tunnel has crack elements in its fracture zone
//      only and the bench's specimen no contact pair before it breaks;
//   3. per run: the peak resident memory by the end of each phase
//      (summary.json "peak_memory_mib"), which says which phase sets the peak;
//   4. per size: whether every thread count gave the same state hash.
//
// Exit code: 0 when every run exited 0, 1 when one did not, 2 for bad options.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_process.hpp"

namespace fs = std::filesystem;
using bench::fixed;
using bench::size_text;
using bench::UsageError;
using nlohmann::json;

namespace {

const char* const kUsage =
    "usage: bench_tunnel_scale [--scene PATH] [--sizes H1,H2,...] [--threads T1,T2,...]\n"
    "                          [--steps N] [--ucs-steps N] [--ucs-repeats N] [--out DIR]\n"
    "                          [--rockfdem PATH] [--bench-ucs PATH] [--set KEY=VALUE ...]\n";

struct Options {
  std::string scene = std::string(ROCKFDEM_SOURCE_DIR) + "/scenes/tunnel-seed-oneshot.toml";
  std::vector<double> sizes{0.35, 0.06};
  std::vector<int> threads{1, 2};
  long steps = 10000;
  long ucs_steps = 0;  // 0: about 1.3e8 triangle-steps, at least 300 steps
  long ucs_repeats = 3;
  std::string out = "/tmp/rockfdem-scale";
  std::string rockfdem = ROCKFDEM_BINARY;
  std::string bench_ucs = BENCH_UCS_BINARY;
  std::vector<std::string> sets;
  std::string command_line;
};

std::string mega(double v) { return fixed(v / 1e6, 2) + " M"; }

std::string or_dash(const std::optional<double>& v, int decimals) {
  return v ? fixed(*v, decimals) : "-";
}

// A comma-separated list of positive numbers.
template <typename T>
std::vector<T> parse_list(const std::string& option, const std::string& list) {
  std::vector<T> values;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !(v > 0) || !std::isfinite(v) || T(v) != v)
      throw UsageError(option + " " + list + ": '" + item + "' is not a positive " +
                       (std::is_integral<T>::value ? "whole number" : "number"));
    values.push_back(T(v));
  }
  if (values.empty()) throw UsageError(option + ": give at least one value");
  return values;
}

long parse_count(const std::string& option, const std::string& v) {
  char* end = nullptr;
  const long n = std::strtol(v.c_str(), &end, 10);
  if (v.empty() || *end != '\0' || n < 1) throw UsageError(option + " " + v + ": expected >= 1");
  return n;
}

void require_executable(const std::string& path, const std::string& option) {
  if (access(path.c_str(), X_OK) != 0)
    throw UsageError("'" + path + "' is not executable; build it or pass " + option + " PATH");
}

Options parse_options(int argc, char** argv) {
  Options o;
  o.command_line = bench::join_quoted(std::vector<std::string>(argv, argv + argc));
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError(a + " needs a value");
      return argv[++i];
    };
    if (a == "--scene")
      o.scene = value();
    else if (a == "--sizes")
      o.sizes = parse_list<double>(a, value());
    else if (a == "--threads")
      o.threads = parse_list<int>(a, value());
    else if (a == "--steps")
      o.steps = parse_count(a, value());
    else if (a == "--ucs-steps")
      o.ucs_steps = parse_count(a, value());
    else if (a == "--ucs-repeats")
      o.ucs_repeats = parse_count(a, value());
    else if (a == "--out")
      o.out = value();
    else if (a == "--rockfdem")
      o.rockfdem = value();
    else if (a == "--bench-ucs")
      o.bench_ucs = value();
    else if (a == "--set")
      o.sets.push_back(value());
    else if (a == "-h" || a == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else {
      throw UsageError("unknown option '" + a + "'");
    }
  }
  require_executable(o.rockfdem, "--rockfdem");
  require_executable(o.bench_ucs, "--bench-ucs");
  if (!fs::is_regular_file(o.scene)) throw UsageError("scene '" + o.scene + "' not found");
  // Coarse to fine: the cheap answers come first.
  std::sort(o.sizes.begin(), o.sizes.end(), std::greater<double>());
  return o;
}

// Engine modules per element-step [ns]: triangles per triangle, crack
// elements per crack element, nodes per node, contact per triangle. The
// tunnel has crack elements in its fracture zone only, and nodes shared
// outside it, where the bench's specimen has both everywhere: per element,
// not per step, is like for like.
using ModuleRates = std::map<std::string, double>;

ModuleRates per_element_ns(const std::map<std::string, double>& seconds, double steps,
                           double triangles, double cracks, double nodes) {
  ModuleRates ns;
  const std::map<std::string, double> count = {
      {"triangles", triangles}, {"cracks", cracks}, {"nodes", nodes}, {"contact", triangles}};
  for (const auto& [module, n] : count) {
    const auto it = seconds.find(module);
    if (it != seconds.end() && n > 0 && steps > 0) ns[module] = 1e9 * it->second / (n * steps);
  }
  return ns;
}

// One tunnel run and the bench beside it.
struct Run {
  double size = 0;
  int threads = 1;
  bench::ChildEnd end;
  std::string status, state_hash;
  std::optional<double> triangles, steps, tunnel_rate, engine_bytes;
  std::map<std::string, double> seconds, peak_mib;  // by phase, from summary.json
  ModuleRates modules;                              // per element-step [ns], summary.json
  double crack_elements = 0, nodes = 0;             // summary.json "counts"
  std::optional<double> ucs_rate, ucs_bytes;        // the median of the repeats
  std::vector<double> ucs_rates;                    // each repeat's, ascending
  ModuleRates ucs_modules;                          // the median repeat's
  int ucs_exit = 0;
};

// One bench repeat: its rate and its modules per element-step.
struct UcsRepeat {
  double rate = 0;
  ModuleRates modules;
};

std::string run_name(const Run& r) {
  return "h_" + size_text(r.size) + "_t" + std::to_string(r.threads);
}

std::vector<std::string> rockfdem_args(const Options& o, const Run& r) {
  std::vector<std::string> a = {o.rockfdem, "run",
                                o.scene,    "-q",
                                "-j",       std::to_string(r.threads),
                                "-o",       (fs::path(o.out) / run_name(r)).string(),
                                "--force"};
  const std::vector<std::string> sets = {
      "mesh.size_near=" + size_text(r.size), "output.vtk=false", "output.plots=false",
      "stages[5].max_steps=" + std::to_string(o.steps), "stages[5].ratio=1e-9"};
  for (const std::string& s : sets) a.insert(a.end(), {"--set", s});
  for (const std::string& s : o.sets) a.insert(a.end(), {"--set", s});
  return a;
}

std::map<std::string, double> number_map(const json& j, const char* key) {
  std::map<std::string, double> m;
  if (j.contains(key) && j[key].is_object())
    for (const auto& [k, v] : j[key].items())
      if (v.is_number()) m[k] = v.get<double>();
  return m;
}

void read_summary(const fs::path& path, Run& r) {
  if (!fs::exists(path)) return;
  const json j = json::parse(bench::read_text(path), nullptr, false);
  if (j.is_discarded()) return;
  if (j.contains("status") && j["status"].is_string()) r.status = j["status"];
  if (j.contains("state_hash") && j["state_hash"].is_string()) r.state_hash = j["state_hash"];
  r.triangles = bench::number_at(j, {"counts", "triangles"});
  r.steps = bench::number_at(j, {"steps"});
  r.tunnel_rate = bench::number_at(j, {"throughput", "triangle_steps_per_second"});
  r.engine_bytes = bench::number_at(j, {"memory_bytes_per_triangle"});
  r.seconds = number_map(j, "timings");
  r.peak_mib = number_map(j, "peak_memory_mib");
  const auto cracks = bench::number_at(j, {"counts", "crack_elements"});
  const auto nodes = bench::number_at(j, {"counts", "nodes"});
  r.crack_elements = cracks.value_or(0);
  r.nodes = nodes.value_or(0);
  if (r.steps && r.triangles && cracks && nodes)
    r.modules =
        per_element_ns(number_map(j, "fdem_modules"), *r.steps, *r.triangles, *cracks, *nodes);
}

// The number after `label` on the first line of `text` that holds it.
std::optional<double> number_after(const std::string& text, const std::string& label) {
  const std::regex re(label + " ([0-9.eE+-]+)");
  std::smatch m;
  if (!std::regex_search(text, m, re)) return std::nullopt;
  return std::strtod(m[1].str().c_str(), nullptr);
}

// The bench's "phases:" line and its counts as per_element_ns.
ModuleRates ucs_modules(const std::string& text) {
  const auto steps = number_after(text, "\\nsteps");
  const auto tri = number_after(text, "\\ntriangles");
  const auto nodes = number_after(text, "\\ntriangles [0-9]+ nodes");
  const auto cracks = number_after(text, "\\ntriangles [0-9]+ nodes [0-9]+ cracks");
  if (!steps || !tri || !nodes || !cracks) return {};
  std::map<std::string, double> seconds;
  for (const char* m : {"triangles", "cracks", "contact", "nodes"})
    if (const auto sec = number_after(text, std::string("phases:.*") + m)) seconds[m] = *sec;
  return per_element_ns(seconds, *steps, *tri, *cracks, *nodes);
}

void run_ucs(const Options& o, Run& r) {
  if (!r.triangles) return;
  const long steps = o.ucs_steps > 0 ? o.ucs_steps : std::max(300L, long(1.3e8 / *r.triangles));
  const std::vector<std::string> args = {o.bench_ucs,
                                         "--triangles",
                                         std::to_string(long(*r.triangles)),
                                         "--steps",
                                         std::to_string(steps),
                                         "--threads",
                                         std::to_string(r.threads),
                                         "--contact",
                                         "1"};
  std::vector<UcsRepeat> repeats;
  for (long k = 1; k <= o.ucs_repeats; ++k) {
    const fs::path log =
        fs::path(o.out) / (run_name(r) + "_ucs" + (k > 1 ? std::to_string(k) : "") + ".log");
    std::cerr << run_name(r) << ": " << bench::join_quoted(args) << " > " << log.string() << '\n';
    const int exit_code = bench::run_logged(args, log.string()).exit_code;
    if (exit_code != 0) r.ucs_exit = exit_code;
    const std::string text = bench::read_text(log);
    if (const auto rate = number_after(text, "triangle-steps/s")) {
      r.ucs_rates.push_back(*rate);
      repeats.push_back({*rate, ucs_modules(text)});
    }
    r.ucs_bytes = number_after(text, "memory");
  }
  std::sort(r.ucs_rates.begin(), r.ucs_rates.end());
  const std::size_t n = r.ucs_rates.size();
  if (n > 0)
    r.ucs_rate = n % 2 ? r.ucs_rates[n / 2] : 0.5 * (r.ucs_rates[n / 2 - 1] + r.ucs_rates[n / 2]);
  // The modules of the repeat at the median (the upper one of an even count).
  std::sort(repeats.begin(), repeats.end(),
            [](const UcsRepeat& a, const UcsRepeat& b) { return a.rate < b.rate; });
  if (!repeats.empty()) r.ucs_modules = repeats[repeats.size() / 2].modules;
}

Run run_one(const Options& o, double size, int threads) {
  Run r;
  r.size = size;
  r.threads = threads;
  const std::vector<std::string> args = rockfdem_args(o, r);
  const fs::path summary = fs::path(o.out) / run_name(r) / "summary.json";
  const fs::path log = fs::path(o.out) / (run_name(r) + ".log");
  std::cerr << run_name(r) << ": " << bench::join_quoted(args) << " > " << log.string() << '\n';
  std::error_code ignored;
  fs::remove(summary, ignored);  // a stale summary must not pass for this run's
  r.end = bench::run_logged(args, log.string());
  read_summary(summary, r);
  std::cerr << run_name(r) << ": exit " << r.end.exit_code << ", " << r.status << ", "
            << fixed(r.end.peak_rss_mib, 0) << " MiB peak\n";
  if (r.end.exit_code != 0) std::cerr << run_name(r) << ": " << bench::last_line(log) << '\n';
  run_ucs(o, r);
  return r;
}

double seconds_of(const Run& r, const char* phase) {
  const auto it = r.seconds.find(phase);
  return it == r.seconds.end() ? 0.0 : it->second;
}

void print_header(const Options& o) {
  const bench::Machine m = bench::this_machine();
  Run example;
  example.size = o.sizes.front();
  example.threads = o.threads.front();
  std::vector<std::string> each = rockfdem_args(o, example);
  std::cout << "## The tunnel at scale: " << fs::path(o.scene).filename().string() << "\n\n"
            << "    " << o.command_line << "\n\n"
            << m.date << ", " << m.host << ", " << m.cpus << " cores (nproc), load average "
            << fixed(m.load_1min, 2) << " at the start. Each run:\n\n    "
            << bench::join_quoted(each) << "\n\n(size and threads as in each row), then "
            << "bench_ucs --contact 1 at the run's triangle count and threads, " << o.ucs_repeats
            << " time(s); the ratio is to the bench's median.\n\n";
}

// The bench's repeats more than 20% apart: the machine's speed changed
// between them (on the 2-core development VM both vCPUs stay fully busy
// with no steal time, yet the bench runs at about 22 M or 31 M
// triangle-steps/s, switching between runs), so one ratio is not settled.
void warn_unsettled(const std::vector<Run>& runs) {
  constexpr double kSpread = 1.2;
  for (const Run& r : runs)
    if (r.ucs_rates.size() > 1 && r.ucs_rates.back() > kSpread * r.ucs_rates.front())
      std::cout << "\n"
                << run_name(r) << ": the bench's repeats span " << mega(r.ucs_rates.front())
                << " - " << mega(r.ucs_rates.back())
                << ": this machine's speed changed during the measurement, and the ratio to "
                   "the median is not settled (tunnel / highest "
                << (r.tunnel_rate ? fixed(*r.tunnel_rate / r.ucs_rates.back(), 2) : "-")
                << ", tunnel / lowest "
                << (r.tunnel_rate ? fixed(*r.tunnel_rate / r.ucs_rates.front(), 2) : "-") << ").\n";
}

void print_runs(const std::vector<Run>& runs) {
  std::cout << "| size_near [m] | triangles | threads | explicit steps | status | mesh [s] | "
               "insitu [s] | total [s] | peak [MiB] | peak [B/tri] | engine [B/tri] | tunnel "
               "tri-steps/s | UCS bench tri-steps/s (median) | UCS lowest - highest | "
               "tunnel / UCS |\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Run& r : runs) {
    const double tri = r.triangles.value_or(0);
    const bool both = r.tunnel_rate && r.ucs_rate && *r.ucs_rate > 0;
    std::cout << "| " << size_text(r.size) << " | " << or_dash(r.triangles, 0) << " | " << r.threads
              << " | " << or_dash(r.steps, 0) << " | "
              << (r.status.empty() ? "exit " + std::to_string(r.end.exit_code) : r.status) << " | "
              << fixed(seconds_of(r, "mesh"), 1) << " | " << fixed(seconds_of(r, "insitu"), 1)
              << " | " << fixed(seconds_of(r, "total"), 1) << " | " << fixed(r.end.peak_rss_mib, 0)
              << " | " << (tri > 0 ? fixed(r.end.peak_rss_mib * 1048576.0 / tri, 0) : "-") << " | "
              << or_dash(r.engine_bytes, 0) << " | " << (r.tunnel_rate ? mega(*r.tunnel_rate) : "-")
              << " | " << (r.ucs_rate ? mega(*r.ucs_rate) : "-") << " | "
              << (r.ucs_rates.empty()
                      ? "-"
                      : mega(r.ucs_rates.front()) + " - " + mega(r.ucs_rates.back()))
              << " | " << (both ? fixed(*r.tunnel_rate / *r.ucs_rate, 2) : "-") << " |\n";
  }
  warn_unsettled(runs);
}

// Each engine module per element-step in the tunnel and in the bench's
// median repeat, and the three modules both run priced at the bench's
// rates over the tunnel's own counts against what the tunnel took.
void print_modules(const std::vector<Run>& runs) {
  std::cout << "\nEach engine module per element-step [ns], tunnel / bench's median repeat "
               "(triangles per triangle, crack elements per crack element, nodes per node, "
               "contact per triangle; the bench's specimen has no contact pair before it "
               "breaks):\n\n"
            << "| run | triangles | crack elements | nodes | contact | triangles + cracks + "
               "nodes: tunnel at the bench's rates / as measured |\n|---|---|---|---|---|---|\n";
  for (const Run& r : runs) {
    if (r.modules.empty()) continue;
    std::cout << "| " << run_name(r);
    for (const char* m : {"triangles", "cracks", "nodes", "contact"}) {
      const auto t = r.modules.find(m);
      const auto b = r.ucs_modules.find(m);
      std::cout << " | " << (t == r.modules.end() ? "-" : fixed(t->second, 1)) << " / "
                << (b == r.ucs_modules.end() ? "-" : fixed(b->second, 1));
    }
    // Weighted by the tunnel's counts, the weights cancel: the ratio of
    // sums of count x rate.
    const double tri = r.triangles.value_or(0);
    double at_bench = 0, measured = 0;
    bool all = true;
    for (const auto& [m, n] : {std::pair<const char*, double>{"triangles", tri},
                               {"cracks", r.crack_elements},
                               {"nodes", r.nodes}}) {
      const auto t = r.modules.find(m);
      const auto b = r.ucs_modules.find(m);
      if (t == r.modules.end() || b == r.ucs_modules.end()) {
        all = false;
        continue;
      }
      at_bench += n * b->second;
      measured += n * t->second;
    }
    std::cout << " | " << (all && measured > 0 ? fixed(at_bench / measured, 2) : "-") << " |\n";
  }
  std::cout << "\n(The last column above 1: the tunnel runs the modules both have faster per "
               "element than the bench.)\n";
}

// The run's phases in the order a tunnel run passes them, then any others.
std::vector<std::string> phase_order(const Run& r) {
  std::vector<std::string> order;
  for (const char* p : {"mesh", "insitu", "continuum_counterpart", "fdem_setup", "fdem", "output"})
    if (r.seconds.count(p)) order.push_back(p);
  for (const auto& entry : r.seconds)
    if (entry.first != "total" && std::find(order.begin(), order.end(), entry.first) == order.end())
      order.push_back(entry.first);
  return order;
}

void print_phases(const std::vector<Run>& runs) {
  std::cout << "\nEach phase's wall time [s] and the process's peak resident memory by its "
               "end [MiB]:\n\n";
  for (const Run& r : runs) {
    std::cout << "- " << run_name(r) << ":";
    for (const std::string& phase : phase_order(r)) {
      const auto peak = r.peak_mib.find(phase);
      std::cout << ' ' << phase << ' ' << fixed(r.seconds.at(phase), 1) << " s"
                << (peak != r.peak_mib.end() ? " (" + fixed(peak->second, 0) + " MiB)" : "") << ';';
    }
    std::cout << '\n';
  }
}

void print_bits(const Options& o, const std::vector<Run>& runs) {
  std::cout << '\n';
  for (double h : o.sizes) {
    std::vector<std::string> hashes;
    for (const Run& r : runs)
      if (r.size == h) hashes.push_back(r.state_hash.empty() ? "(none)" : r.state_hash);
    const bool same = std::all_of(hashes.begin(), hashes.end(),
                                  [&](const std::string& x) { return x == hashes.front(); });
    std::cout << "size_near " << size_text(h) << ": state hash " << hashes.front()
              << (hashes.size() < 2 ? " (one thread count)"
                  : same            ? ", the same for every thread count"
                                    : ": DIFFERS between thread counts")
              << '\n';
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options o = parse_options(argc, argv);
    fs::create_directories(o.out);
    std::vector<Run> runs;
    for (double h : o.sizes)
      for (int t : o.threads) runs.push_back(run_one(o, h, t));
    print_header(o);
    print_runs(runs);
    print_modules(runs);
    print_phases(runs);
    print_bits(o, runs);
    for (const Run& r : runs)
      if (r.end.exit_code != 0 || r.ucs_exit != 0) return 1;
    return 0;
  } catch (const UsageError& e) {
    std::cerr << "bench_tunnel_scale: " << e.what() << '\n' << kUsage;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "bench_tunnel_scale: " << e.what() << '\n';
    return 1;
  }
}
