// gmsh resets the process's OpenMP thread count to 1 on initialize and to
// its own thread count while meshing; meshing must leave it as it was.
#include <gtest/gtest.h>
#include <omp.h>

#include "rockfdem/mesh/build.hpp"
#include "rockfdem/mesh/msh_io.hpp"
#include "scratch_dir.hpp"

namespace rockfdem::mesh {
namespace {

MeshSpec small_ucs(int threads) {
  MeshSpec s;
  s.kind = ModelKind::kUcs;
  s.size.size_near = 0.01;
  s.size.threads = threads;
  return s;
}

class OpenMpThreads : public ::testing::Test {
 protected:
  void SetUp() override { saved_ = omp_get_max_threads(); }
  void TearDown() override { omp_set_num_threads(saved_); }
  int saved_ = 1;
};

TEST_F(OpenMpThreads, meshing_restores_the_thread_count) {
  omp_set_num_threads(3);
  MeshReport r;
  build_mesh(small_ucs(0), &r);
  EXPECT_EQ(omp_get_max_threads(), 3);
  EXPECT_EQ(r.gmsh_threads, 3);  // 0: gmsh takes OpenMP's count
}

TEST_F(OpenMpThreads, explicit_gmsh_threads_do_not_leak_into_openmp) {
  omp_set_num_threads(5);
  MeshReport r;
  build_mesh(small_ucs(2), &r);
  EXPECT_EQ(r.gmsh_threads, 2);
  EXPECT_EQ(omp_get_max_threads(), 5);
}

TEST_F(OpenMpThreads, writing_and_reading_restore_the_thread_count) {
  omp_set_num_threads(4);
  const Mesh m = build_mesh(small_ucs(1));
  const std::string path = test::scratch_path("rockfdem_threads.msh");
  write_msh(m, path);
  EXPECT_EQ(omp_get_max_threads(), 4);
  read_msh({path, {}, {}, "", {}});
  EXPECT_EQ(omp_get_max_threads(), 4);
}

TEST_F(OpenMpThreads, a_failed_build_restores_the_thread_count) {
  omp_set_num_threads(3);
  MeshSpec s = small_ucs(0);
  s.specimen.height = 0;
  EXPECT_ANY_THROW(build_mesh(s));
  EXPECT_EQ(omp_get_max_threads(), 3);
}

}  // namespace
}  // namespace rockfdem::mesh
