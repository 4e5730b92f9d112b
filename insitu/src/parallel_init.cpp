// The process-wide runtime the AMG preconditioner needs. PETSc's GAMG works
// on PETSc objects, which need PETSc (and MPI under it) started even in a
// serial program; deal.II's MPI_InitFinalize starts MPI (and Kokkos/PETSc/
// SLEPc where they are configured) and stops it at the end of main().
//
// Two side effects matter to the rest of rockfdem:
//   * max_num_threads = 1 limits deal.II's TBB pool: the implicit stage runs
//     on one core; the explicit engine's OpenMP threads are separate.
//   * The OpenMP thread count must survive. deal.II leaves OpenMP alone, but
//     Kokkos' initialisation inside Trilinos may not, so the count in force
//     before construction is put back afterwards.
#include <deal.II/base/mpi.h>
#include <mpi.h>
#include <omp.h>

#include "rockfdem/insitu/insitu.hpp"

namespace rockfdem::insitu {

struct ScopedParallelInit::Impl {
  std::unique_ptr<dealii::Utilities::MPI::MPI_InitFinalize> mpi;
};

namespace {
// MPI wants argc/argv; programs without them hand over this stand-in.
int g_dummy_argc = 1;
char g_dummy_name[] = "rockfdem";
char* g_dummy_argv_storage[] = {g_dummy_name, nullptr};
char** g_dummy_argv = g_dummy_argv_storage;
}  // namespace

ScopedParallelInit::ScopedParallelInit(int& argc, char**& argv) : impl_(new Impl) {
  const int omp_threads = omp_get_max_threads();
  // A second owner (another ScopedParallelInit, or a caller that started MPI
  // itself) keeps the runtime; this object then does nothing.
  if (!active())
    impl_->mpi = std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(argc, argv, 1);
  omp_set_num_threads(omp_threads);
}

ScopedParallelInit::ScopedParallelInit() : ScopedParallelInit(g_dummy_argc, g_dummy_argv) {}

ScopedParallelInit::~ScopedParallelInit() = default;

bool ScopedParallelInit::active() {
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  return initialised && !finalised;
}

}  // namespace rockfdem::insitu
