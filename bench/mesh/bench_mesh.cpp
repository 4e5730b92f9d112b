// bench_mesh: meshing time and triangle count for the seed's horseshoe tunnel
// at several near sizes.
//
//   build-mesh/bench/mesh/bench_mesh                        # 3 sizes: ~20k, ~200k, ~2M
//   build-mesh/bench/mesh/bench_mesh --near 0.2 --near 0.06 --far 5 --threads 2
//
// Model (the seed scene's tunnel in the domain asked for by the benchmark):
//
//        +---------------- 100 m ----------------+
//        |              size_far                 |
//        |          .-''''''''''-.               |
//        |        /  fracture zone \  4 m        |
//        |       |    .-''''-.     |             |
//        |       |   | core  | <- 0.2 m lining   |  100 m
//        |       |   |_______|  horseshoe        |
//        |        \  span 11.3, height 8.8  /    |
//        |          '-..........-'               |
//        +---------------------------------------+
//
// size_near applies at the tunnel, in the core, lining and fracture zone;
// the size grows linearly to size_far at the nearest outer side (automatic
// grading). Times are wall-clock for build_mesh: gmsh start, geometry,
// 2D meshing and extraction into the Mesh record.
#include <omp.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "rockfdem/mesh/build.hpp"

namespace {

struct Options {
  std::vector<double> near;
  double far = 5;
  int threads = 0;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    const double value = std::atof(argv[i + 1]);
    if (key == "--near")
      o.near.push_back(value);
    else if (key == "--far")
      o.far = value;
    else if (key == "--threads")
      o.threads = static_cast<int>(value);
    else
      std::fprintf(stderr, "unknown option %s\n", key.c_str()), std::exit(2);
  }
  if (o.near.empty()) o.near = {0.22, 0.06, 0.019};
  return o;
}

rockfdem::mesh::MeshSpec seed_tunnel(double near, double far, int threads) {
  rockfdem::mesh::MeshSpec s;
  s.tunnel.shape = rockfdem::mesh::TunnelShape::kHorseshoe;
  s.tunnel.span = 11.3, s.tunnel.height = 8.8;
  s.tunnel.lining_thickness = 0.2, s.tunnel.fracture_zone = 4;
  s.domain = {100, 100, 0, 0};
  s.size.size_near = near, s.size.size_far = far, s.size.threads = threads;
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  std::printf("# command:");
  for (int i = 0; i < argc; ++i) std::printf(" %s", argv[i]);
  std::printf(
      "\n# horseshoe 11.3 x 8.8 m, lining 0.2 m, fracture zone 4 m, domain 100 x 100 m,"
      " size_far %g m, OpenMP threads %d\n",
      o.far, omp_get_max_threads());
  std::printf("%10s %12s %12s %12s %12s %10s %8s\n", "near_m", "triangles", "vertices", "min_alt_m",
              "min_angle", "seconds", "threads");
  for (double near : o.near) {
    rockfdem::mesh::MeshReport r;
    rockfdem::mesh::build_mesh(seed_tunnel(near, o.far, o.threads), &r);
    std::printf("%10.4g %12zu %12zu %12.4g %12.2f %10.3f %8d\n", near, r.n_triangles, r.n_vertices,
                r.min_altitude, r.min_angle_deg, r.seconds, r.gmsh_threads);
    std::fflush(stdout);
  }
  return 0;
}
