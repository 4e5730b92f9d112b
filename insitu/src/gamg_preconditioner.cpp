// GAMG's settings: PETSc's defaults as its options database gives them
// (Chebyshev smoothing with Jacobi, two sweeps, one smoothing step of the
// prolongator, the graph squared on the finest level), set here by call so
// that no PETSC_OPTIONS in the environment changes a run. Squaring the
// finest graph makes larger aggregates: at 420k triangles the hierarchy is
// half as large and a cycle half as dear as without it, for 18 iterations
// against 15.
#include "gamg_preconditioner.hpp"

#include <cmath>
#include <string>

#include "rockfdem/error.hpp"

namespace rockfdem::insitu {

namespace {

void check(const PetscErrorCode code, const char* what) {
  if (code != 0)
    throw NumericalError(std::string("insitu: PETSc failed in ") + what + " (error code " +
                         std::to_string(static_cast<int>(code)) + ")");
}

// Sequential vectors that borrow the caller's arrays at each application.
void make_headers(Mat matrix, Vec& in, Vec& out) {
  PetscInt n = 0;
  check(MatGetLocalSize(matrix, &n, nullptr), "MatGetLocalSize");
  check(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n, nullptr, &in), "VecCreateSeqWithArray");
  check(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n, nullptr, &out), "VecCreateSeqWithArray");
}

// The rigid motions, orthonormalised (MatNullSpaceCreate asks for it).
MatNullSpace near_null_space(const std::array<std::vector<double>, 3>& modes) {
  std::array<Vec, 3> v{};
  for (std::size_t k = 0; k < 3; ++k) {
    check(VecCreateSeq(PETSC_COMM_SELF, static_cast<PetscInt>(modes[k].size()), &v[k]),
          "VecCreateSeq");
    PetscScalar* a = nullptr;
    check(VecGetArray(v[k], &a), "VecGetArray");
    for (std::size_t i = 0; i < modes[k].size(); ++i) a[i] = modes[k][i];
    check(VecRestoreArray(v[k], &a), "VecRestoreArray");
    for (std::size_t j = 0; j < k; ++j) {
      PetscScalar c = 0;
      check(VecDot(v[k], v[j], &c), "VecDot");
      check(VecAXPY(v[k], -c, v[j]), "VecAXPY");
    }
    check(VecNormalize(v[k], nullptr), "VecNormalize");
  }
  MatNullSpace space = nullptr;
  check(MatNullSpaceCreate(PETSC_COMM_SELF, PETSC_FALSE, 3, v.data(), &space),
        "MatNullSpaceCreate");
  for (Vec& x : v) VecDestroy(&x);  // the null space holds its own references
  return space;
}

void apply_to_arrays(Vec in, Vec out, const double* src, double* dst, Mat matrix, PC pc) {
  check(VecPlaceArray(in, src), "VecPlaceArray");
  check(VecPlaceArray(out, dst), "VecPlaceArray");
  check(matrix ? MatMult(matrix, in, out) : PCApply(pc, in, out), matrix ? "MatMult" : "PCApply");
  check(VecResetArray(in), "VecResetArray");
  check(VecResetArray(out), "VecResetArray");
}

// What the set-up keeps for a numeric rebuild that never comes
// (PCSetReusePreconditioner keeps this hierarchy through changed values,
// and a rebuild is a new object): the Galerkin and prolongator products'
// intermediate data and the near-null space's three vectors.
void drop_setup_data(PC pc, Mat matrix) {
  PetscInt levels = 0;
  check(PCMGGetLevels(pc, &levels), "PCMGGetLevels");
  for (PetscInt l = 0; l < levels; ++l) {
    KSP smoother = nullptr;
    check(PCMGGetSmoother(pc, l, &smoother), "PCMGGetSmoother");
    Mat op = nullptr;
    check(KSPGetOperators(smoother, &op, nullptr), "KSPGetOperators");
    check(MatProductClear(op), "MatProductClear");
    if (l == 0) continue;  // no interpolation into the coarsest level
    Mat interpolation = nullptr;
    check(PCMGGetInterpolation(pc, l, &interpolation), "PCMGGetInterpolation");
    check(MatProductClear(interpolation), "MatProductClear");
  }
  check(MatSetNearNullSpace(matrix, nullptr), "MatSetNearNullSpace");
}

}  // namespace

PetscProduct::PetscProduct(Mat matrix) : matrix_(matrix) { make_headers(matrix, in_, out_); }

PetscProduct::~PetscProduct() {
  VecDestroy(&in_);
  VecDestroy(&out_);
}

void PetscProduct::apply(const double* src, double* dst) const {
  apply_to_arrays(in_, out_, src, dst, matrix_, nullptr);
}

GamgPreconditioner::GamgPreconditioner(Mat matrix,
                                       const std::array<std::vector<double>, 3>& rigid_motions) {
  check(MatSetBlockSize(matrix, 2), "MatSetBlockSize");  // aggregate vertices, not dofs
  MatNullSpace space = near_null_space(rigid_motions);
  check(MatSetNearNullSpace(matrix, space), "MatSetNearNullSpace");
  MatNullSpaceDestroy(&space);
  check(PCCreate(PETSC_COMM_SELF, &pc_), "PCCreate");
  check(PCSetType(pc_, PCGAMG), "PCSetType");
  check(PCGAMGSetAggressiveLevels(pc_, 1), "PCGAMGSetAggressiveLevels");
  check(PCSetOperators(pc_, matrix, matrix), "PCSetOperators");
  check(PCSetUp(pc_), "PCSetUp (GAMG's hierarchy)");
  drop_setup_data(pc_, matrix);
  // PCApply would build anew once the matrix's values change: the caller
  // decides when a hierarchy is built (a new object).
  check(PCSetReusePreconditioner(pc_, PETSC_TRUE), "PCSetReusePreconditioner");
  make_headers(matrix, in_, out_);
}

GamgPreconditioner::~GamgPreconditioner() {
  VecDestroy(&in_);
  VecDestroy(&out_);
  PCDestroy(&pc_);
}

void GamgPreconditioner::apply(const double* src, double* dst) const {
  apply_to_arrays(in_, out_, src, dst, nullptr, pc_);
}

}  // namespace rockfdem::insitu
