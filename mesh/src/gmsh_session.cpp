#include "gmsh_session.hpp"

#include <gmsh.h>
#include <omp.h>

#include <atomic>
#include <stdexcept>

namespace rockfdem::mesh::detail {
namespace {
// gmsh holds one global model: two sessions at once would finalize each
// other's state, so a second one is a programming error.
std::atomic<bool> g_session_open{false};
}  // namespace

GmshSession::GmshSession(int threads, bool verbose) {
  if (g_session_open.exchange(true))
    throw std::logic_error("gmsh session: another session is already open");
  saved_omp_threads_ = omp_get_max_threads();
  threads_ = threads > 0 ? threads : saved_omp_threads_;
  try {
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
    gmsh::option::setNumber("General.Terminal", verbose ? 1 : 0);
    gmsh::option::setNumber("General.Verbosity", verbose ? 5 : 0);
    gmsh::option::setNumber("General.NumThreads", threads_);
    // gmsh 4.8 meshes curves and surfaces in parallel with shared size-field
    // state: measured on the seed tunnel with 2 threads, triangle counts
    // changed from run to run and the smallest angle fell from 35 to 6-11
    // degrees. Curves and surfaces are therefore meshed one at a time.
    gmsh::option::setNumber("Mesh.MaxNumThreads1D", 1);
    gmsh::option::setNumber("Mesh.MaxNumThreads2D", 1);
  } catch (const std::string& what) {
    omp_set_num_threads(saved_omp_threads_);
    g_session_open = false;
    throw std::runtime_error("gmsh session: initialize failed: " + what);
  }
  omp_set_num_threads(saved_omp_threads_);
}

GmshSession::~GmshSession() {
  try {
    gmsh::finalize();
  } catch (...) {
    // Nothing useful can be done while unwinding; the count is restored below.
  }
  omp_set_num_threads(saved_omp_threads_);
  g_session_open = false;
}

}  // namespace rockfdem::mesh::detail
