// The in-situ stage: the implicit elastic state a tunnel model starts from.
//
// Input: the shared triangle mesh (rockfdem/mesh/mesh.hpp) and an InsituSpec
// (far-field stresses, materials per zone, the core-softening sequence).
// Output: one InsituField per softening factor alpha, with a stress per
// triangle and a displacement per vertex, in the mesh's own order, ready to
// become the explicit engine's initial state.
//
// Sign conventions
//   * Input stresses (FarField::sH, sV, sZ) are magnitudes of COMPRESSION:
//     positive numbers, as geologists quote them.
//   * Output stresses (InsituField::stress) follow continuum mechanics:
//     TENSION POSITIVE, so an in-situ compression of 18.2 MPa comes back
//     as sxx = -18.2e6.
//   * Displacements are those CAUSED BY THE EXCAVATION (softening or removing
//     the core), measured from the in-situ state, with the rigid motion that
//     best fits the outer boundary removed: "the far field stays put".
//
// Units: SI throughout (Pa, m, N/m^3).
//
// No deal.II type appears here: the implementation (insitu/src) is a deal.II
// program, but callers only see plain records.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::insitu {

// ---------------------------------------------------------------------------
// Runtime
// ---------------------------------------------------------------------------

/// Creates the MPI runtime (and limits deal.II's TBB pool to one thread) for
/// the lifetime of the object. PETSc's algebraic multigrid needs it: create
/// exactly one at the top of main(), before any solve_insitu() call. The
/// OpenMP thread count in force before construction is restored afterwards,
/// so the explicit engine keeps all its threads. Without one, solve_insitu()
/// still works but uses the direct solver (and says so in InsituField::solver).
class ScopedParallelInit {
 public:
  ScopedParallelInit(int& argc, char**& argv);
  ScopedParallelInit();  ///< for programs without command-line arguments
  ~ScopedParallelInit();
  ScopedParallelInit(const ScopedParallelInit&) = delete;
  ScopedParallelInit& operator=(const ScopedParallelInit&) = delete;

  /// True once some ScopedParallelInit (or another owner) has started MPI.
  static bool active();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// ---------------------------------------------------------------------------
// Input
// ---------------------------------------------------------------------------

/// Far-field principal stresses, compression positive [Pa].
struct FarField {
  double sH = 0;         ///< major horizontal stress (acts along angle_deg)
  double sV = 0;         ///< vertical stress (acts normal to angle_deg)
  double angle_deg = 0;  ///< direction of sH, counter-clockwise from +x [deg]
  /// Out-of-plane stress; unset: nu_rock * (sH + sV) (plane strain from rest).
  std::optional<double> sZ;
};

/// Optional lithostatic gradient. With unit_weight > 0 the stresses grow with
/// depth: sV(y) = sV + gamma (reference_y - y), sH(y) = sH + k0 gamma
/// (reference_y - y) with k0 = sH / sV, and the self weight acts as a body
/// force (0, -gamma). Requires angle_deg = 0 and far-field loading.
struct Gravity {
  double unit_weight = 0;  ///< gamma [N/m^3]; 0 = no gradient
  double reference_y = 0;  ///< y where FarField holds [m]
};

/// What is applied on the outer boundary of the box.
enum class BoundaryLoading {
  kFarField,     ///< traction sigma0 . n (the box is "far enough")
  kKirschExact,  ///< traction of the exact Kirsch field around a hole of
                 ///< radius kirsch_radius centred at the origin
                 ///< (verification: removes the finite-box error at alpha = 0)
};

struct ElasticMaterial {
  double E = 0;   ///< Young's modulus [Pa]
  double nu = 0;  ///< Poisson's ratio (plane strain)
};

/// Materials per zone. A zone present in the mesh must have its material:
/// rock for kRock; core for kCore (and for kLining before the lining is
/// installed: until then the ring is ground still to be excavated); lining
/// for kLining once installed.
struct ZoneMaterials {
  std::optional<ElasticMaterial> rock;
  std::optional<ElasticMaterial> core;
  std::optional<ElasticMaterial> lining;
};

/// The lining ring (zone kLining). Inactive: the ring is ground, softened and
/// removed with the core. Active: from the first stage whose alpha <=
/// install_alpha the ring is lining material, stress-free when installed on
/// the ground as deformed by the previous stage, and stays when the core goes.
struct LiningStage {
  bool active = false;
  double install_alpha = 0.01;  ///< the seed installs at alpha = 0.01
};

enum class LinearSolver {
  kAuto,    ///< direct below direct_below_dofs, else AMG-CG (direct if CG fails)
  kAmgCg,   ///< PETSc GAMG (rigid-body near-null space) + CG
  kDirect,  ///< UMFPACK
};

struct SolverSpec {
  LinearSolver kind = LinearSolver::kAuto;
  /// CG stops when ||residual|| <= tolerance * ||in-situ nodal forces||.
  /// 1e-8 leaves the fields within 4e-7 of the largest displacement and
  /// 1e-7 of the largest stress of a converged solve at 420k triangles,
  /// a thirty-fifth of the finest shipped mesh's own error, in about a fifth
  /// less time than 1e-10 (docs/benchmarks.md, "The in-situ solver's
  /// tolerance: time against error").
  double tolerance = 1e-8;
  int max_iterations = 1000;
  std::size_t direct_below_dofs = 20000;
};

struct InsituField;

struct InsituSpec {
  FarField far_field;
  Gravity gravity;
  BoundaryLoading loading = BoundaryLoading::kFarField;
  double kirsch_radius = 0;  ///< [m], for BoundaryLoading::kKirschExact
  ZoneMaterials materials;
  LiningStage lining;
  /// Core softening factors, strictly decreasing, each in [0, 1]. alpha
  /// scales the core's whole stress (reference section 5); 0 removes it.
  std::vector<double> alphas{1.0};
  /// The alphas whose fields keep their arrays (stress, active, ux, uy);
  /// the others come back with their solver report only, so that a
  /// caller that needs two fields of a long sequence does not hold them
  /// all. Empty: every alpha's.
  std::vector<double> keep_fields;
  SolverSpec solver;
  /// Called with each field once solved, before the next alpha's solve and
  /// before keep_fields applies: a caller that reads a few figures of most
  /// fields takes them here, and may move the arrays out to keep only the
  /// fields it needs whole (the field is not read again).
  std::function<void(InsituField&)> on_field;
};

// ---------------------------------------------------------------------------
// Output: the hand-off record
// ---------------------------------------------------------------------------

/// Plane-strain stress of one triangle, TENSION POSITIVE [Pa].
struct Stress {
  double sxx = 0, syy = 0, sxy = 0, szz = 0;
};

struct InsituField {
  double alpha = 1;
  bool lining_installed = false;

  std::vector<Stress> stress;        ///< per mesh triangle (0 where removed)
  std::vector<std::uint8_t> active;  ///< per mesh triangle: 1 if in the system
  std::vector<double> ux, uy;        ///< per mesh vertex [m] (0 where removed)

  // Solver report.
  std::string solver;  ///< "direct", "amg-cg", "direct (cg failed: ...)"
  int iterations = 0;  ///< CG iterations (0 for direct)
  /// AMG-CG: the hierarchy built for an earlier alpha (same grid) served this
  /// solve; false when it was built for this one.
  bool preconditioner_reused = false;
  std::size_t n_dofs = 0;
  std::size_t n_cells = 0;
  double setup_seconds = 0;  ///< triangulation, dofs, sparsity
  double assembly_seconds = 0;
  double solve_seconds = 0;  ///< including AMG setup / factorisation
  /// AMG-CG: of solve_seconds, building GAMG's hierarchy (0 where an
  /// earlier alpha's hierarchy served).
  double preconditioner_seconds = 0;
  double postprocess_seconds = 0;  ///< stresses, displacements, checks
  double total_seconds = 0;
  /// ||K u - f|| over free dofs / ||in-situ nodal forces||: the equilibrium
  /// the solve reached (the explicit engine's unbalanced-force ratio).
  double unbalanced_ratio = 0;
  /// largest reaction at the three rigid-motion constraints / ||in-situ nodal
  /// forces||: ~0 when the loads are self-equilibrated, as they must be.
  double reaction_ratio = 0;
};

/// Solves one elastic state per spec.alphas entry. Throws rockfdem::InputError
/// for bad input (one message saying what to change).
std::vector<InsituField> solve_insitu(const mesh::Mesh& mesh, const InsituSpec& spec);

/// Throws rockfdem::InputError if spec (with this mesh) cannot be solved;
/// solve_insitu calls it first. Cheap: no deal.II.
void validate(const mesh::Mesh& mesh, const InsituSpec& spec);

/// A fixed-width table of the per-stage timings and solver figures.
std::string timing_table(const std::vector<InsituField>& fields);

// ---------------------------------------------------------------------------
// Closed forms (reference section 5) and the comparison with them
// ---------------------------------------------------------------------------

/// A circular hole of radius a at the origin in an infinite plate.
struct KirschCase {
  double a = 0;           ///< hole radius [m]
  double sH = 0, sV = 0;  ///< far field, compression positive [Pa]
  double angle_deg = 0;   ///< direction of sH from +x [deg]
  double E = 0, nu = 0;   ///< rock (plane strain)
};

/// Kirsch stress at (x, y), r >= a; TENSION POSITIVE.
Stress kirsch_stress(const KirschCase& k, double x, double y);

/// Excavation-induced radial displacement at radius r >= a, angle theta
/// from +x, outward positive [m].
double kirsch_radial_displacement(const KirschCase& k, double r, double theta);

/// Wall displacement caused by softening a circular core (same E, nu as the
/// rock) from 1 to alpha in hydrostatic far field p (compression positive):
/// (S a/(2K)) [(K + mu)/(alpha K + mu) - 1] with S = -p, K = lambda + mu.
/// Outward positive [m].
double core_softening_wall_displacement(double alpha, double p, double a, double E, double nu);

struct KirschRow {
  int triangle = 0;
  double x = 0, y = 0, r = 0, theta = 0;  ///< centroid
  double srr = 0, stt = 0, srt = 0;       ///< FE (tension positive)
  double srr_exact = 0, stt_exact = 0, srt_exact = 0;
};

struct KirschComparison {
  /// sqrt(sum A |s_h - s|^2 / sum A |s|^2) over triangles whose centroid lies
  /// in a <= r <= 5a, |s|^2 = sxx^2 + syy^2 + 2 sxy^2, s at the centroid.
  double stress_rel_l2 = 0;
  /// sqrt(sum (ur_h - ur)^2 / sum ur^2) over the wall vertices (r = a).
  double wall_ur_rel_l2 = 0;
  double wall_ur_mean = 0, wall_ur_mean_exact = 0;  ///< [m]
  std::size_t n_triangles = 0, n_wall_vertices = 0;
  std::vector<KirschRow> rows;  ///< one per compared triangle, for a CSV
};

/// Compares an alpha = 0 field (open hole) with Kirsch. The wall vertices are
/// those on kExcavation edges, or within 1e-6 a of r = a if none is tagged.
KirschComparison compare_kirsch(const mesh::Mesh& mesh, const InsituField& field,
                                const KirschCase& k);

}  // namespace rockfdem::insitu
