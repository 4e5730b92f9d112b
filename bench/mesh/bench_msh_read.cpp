// bench_msh_read: what reading a user's .msh in a child process costs
// (read_msh: checks here, gmsh's read in a forked child, the record back
// through a pipe) against the same read in this process.
//
//   build/bench/mesh/bench_msh_read                       # near 0.5, 0.22, 0.06 m
//   build/bench/mesh/bench_msh_read --near 0.5 --repeats 21
//   build/bench/mesh/bench_msh_read --file mesh.msh      # a file of yours
//
// Each mesh is the seed's horseshoe tunnel (as bench_mesh) at the near size
// asked for, written by write_msh (gmsh 4.1 ASCII, as `rockfdem mesh`
// writes mesh.msh) to a temporary file, then read `repeats` times each
// way, alternating (--file: that file, read with the group names write_msh
// gives). Printed: the file's size, the record's counts and the
// median wall time of each way; the two meshes are compared bit for bit.
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "msh_read.hpp"
#include "rockfdem/mesh/build.hpp"
#include "rockfdem/mesh/msh_io.hpp"

namespace {

using rockfdem::mesh::Mesh;

rockfdem::mesh::MeshSpec seed_tunnel(double near) {
  rockfdem::mesh::MeshSpec s;
  s.tunnel.shape = rockfdem::mesh::TunnelShape::kHorseshoe;
  s.tunnel.span = 11.3, s.tunnel.height = 8.8;
  s.tunnel.lining_thickness = 0.2, s.tunnel.fracture_zone = 4;
  s.domain = {100, 100, 0, 0};
  s.size.size_near = near, s.size.size_far = 5;
  return s;
}

bool same(const Mesh& a, const Mesh& b) {
  const auto edge = [](const Mesh& m) {
    std::vector<int> v;
    for (const auto& e : m.edges) v.insert(v.end(), {e.a, e.b, e.tag});
    return v;
  };
  return a.x == b.x && a.y == b.y && a.triangles == b.triangles && a.zone == b.zone &&
         a.fracture == b.fracture && edge(a) == edge(b);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<double> nears;
  std::vector<std::string> files;
  int repeats = 11;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--near")
      nears.push_back(std::atof(argv[i + 1]));
    else if (key == "--file")
      files.push_back(argv[i + 1]);
    else if (key == "--repeats")
      repeats = std::max(1, std::atoi(argv[i + 1]));
    else
      std::fprintf(stderr, "unknown option %s\n", key.c_str()), std::exit(2);
  }
  if (nears.empty() && files.empty()) nears = {0.5, 0.22, 0.06};
  std::printf("# command:");
  for (int i = 0; i < argc; ++i) std::printf(" %s", argv[i]);
  std::printf("\n%8s %10s %10s %10s %12s %12s %10s %6s\n", "near_m", "bytes", "triangles",
              "vertices", "in_proc_ms", "child_ms", "extra_ms", "same");
  const std::string path = "/tmp/rockfdem_bench_msh_read_" + std::to_string(getpid()) + ".msh";
  const auto measure = [&](const std::string& file, const std::string& label) {
    struct stat st {};
    ::stat(file.c_str(), &st);
    const rockfdem::mesh::MshFileSpec spec{file, {}, {}, "", {}};
    std::vector<double> here, child;
    Mesh a, b;
    using Clock = std::chrono::steady_clock;
    for (int r = 0; r < repeats; ++r) {
      auto t0 = Clock::now();
      a = rockfdem::mesh::detail::read_msh_in_process(spec);
      auto t1 = Clock::now();
      b = rockfdem::mesh::read_msh(spec);
      auto t2 = Clock::now();
      here.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
      child.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
    }
    const double h = median(here), c = median(child);
    std::printf("%8s %10lld %10zu %10zu %12.1f %12.1f %10.1f %6s\n", label.c_str(),
                static_cast<long long>(st.st_size), a.n_triangles(), a.n_vertices(), h, c, c - h,
                same(a, b) ? "yes" : "NO");
    std::fflush(stdout);
  };
  for (double near : nears) {
    rockfdem::mesh::write_msh(rockfdem::mesh::build_mesh(seed_tunnel(near)), path);
    char label[32];
    std::snprintf(label, sizeof label, "%.3g", near);
    measure(path, label);
  }
  for (const std::string& file : files) measure(file, "file");
  std::remove(path.c_str());
  return 0;
}
