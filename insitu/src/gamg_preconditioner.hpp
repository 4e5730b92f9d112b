// PETSc's smoothed-aggregation AMG (GAMG) and the matrix product, on plain
// arrays: the in-situ stage keeps its vectors in deal.II's Vector and hands
// their storage to PETSc, copying nothing.
#pragma once

#include <petscksp.h>

#include <array>
#include <vector>

namespace rockfdem::insitu {

/// dst = A src, with A a sequential PETSc matrix the caller keeps alive.
class PetscProduct {
 public:
  explicit PetscProduct(Mat matrix);
  ~PetscProduct();
  PetscProduct(const PetscProduct&) = delete;
  PetscProduct& operator=(const PetscProduct&) = delete;
  void apply(const double* src, double* dst) const;

 private:
  Mat matrix_;
  Vec in_ = nullptr, out_ = nullptr;  ///< headers without storage of their own
};

/// One V-cycle of GAMG, built on a matrix of 2 dofs per vertex with the
/// rigid motions (two translations and the rotation, in dof order) as its
/// near-null space. The hierarchy stays when the matrix's values change:
/// its finest level (residual, Jacobi-Chebyshev smoother) then works with
/// the matrix as it is, the coarser levels with the build's.
class GamgPreconditioner {
 public:
  GamgPreconditioner(Mat matrix, const std::array<std::vector<double>, 3>& rigid_motions);
  ~GamgPreconditioner();
  GamgPreconditioner(const GamgPreconditioner&) = delete;
  GamgPreconditioner& operator=(const GamgPreconditioner&) = delete;
  void apply(const double* src, double* dst) const;

 private:
  PC pc_ = nullptr;
  Vec in_ = nullptr, out_ = nullptr;
};

}  // namespace rockfdem::insitu
