// The in-situ stage as a deal.II program.
//
// This file reads like a deal.II tutorial (step-8 for elasticity, step-18 for
// the staged loop): one class, InsituProblem, whose constructor takes the
// mesh and the spec and whose run() solves one elastic state per softening
// factor alpha. The finite element work of rockfdem lives in two deal.II
// translation units: this one (the elastic stage) and plastic_problem.cpp
// (the Mohr-Coulomb continuum on the same grid); parallel_init.cpp
// includes deal.II only to start MPI.
//
// ## The mathematics
//
// The ground is at rest under an initial stress sigma0(x) (tension positive):
// uniform, or growing with depth under its own weight b = (0, -gamma). sigma0
// is in equilibrium with b and with the far-field traction t = sigma0 . n on
// the outer boundary of the box:
//
//     div sigma0 + b = 0 in the domain,     sigma0 . n = t on the box.     (1)
//
// We seek the displacement u measured FROM this state. In each zone the
// stress is an initial stress plus an elastic response,
//
//     rock:                sigma = sigma0 + C_rock : eps(u)
//     core (softened):     sigma = alpha (sigma0 + C_core : eps(u))        (2)
//     lining (installed):  sigma = C_lining : (eps(u) - eps_install)
//
// and the weak form of equilibrium, for every test function v, is
//
//     sum_zones int D eps(u) : eps(v) = int_box t . v + int b_zone . v
//                                       - sum_zones int s0_zone : eps(v),   (3)
//
// with D = C_rock, alpha C_core, C_lining, s0 = sigma0, alpha sigma0,
// -C_lining eps_install, and b_zone = b, alpha b, 0 respectively. By (1) the
// right-hand side vanishes identically when every zone carries sigma0 (alpha
// = 1, no lining): nothing moves and the stress IS sigma0, element by element
// (the patch test). For alpha < 1 the right-hand side is what the softened
// core no longer carries, (1 - alpha) int_core (sigma0 : eps(v) - b . v),
// i.e. (1 - alpha) times the in-situ traction on the excavation boundary:
// the familiar internal-pressure release, arising here on its own. For
// alpha = 0 the core is not in the system at all (its cells are left out of
// the triangulation) and the excavation boundary is traction-free: the open
// hole, which with exact Kirsch tractions on the box reproduces Kirsch.
//
// Scaling the core's WHOLE stress by alpha (not only its modulus) is what
// reference section 5 asks: when the in-situ state was reached by deforming
// from zero and the modulus is then scaled, the stress scales with it. Scaling
// only C_core would release nothing.
//
// P1 triangles have constant strain, so one quadrature point (the centroid)
// integrates (3) exactly: D and eps(v) are constant per cell, sigma0 and b.v
// are at most linear. On the box edges the traction is integrated with a
// 3-point Gauss rule (exact for the linear gravity traction times a linear v;
// accurate for the smooth Kirsch traction).
//
// ## Gravity: the weight that leaves with the core
//
// With a gradient, sigma0 balances the self weight b, and the box tractions
// carry the weight of everything inside, the core included. Softening or
// removing the core takes (1 - alpha) of its weight away (and an installed
// lining is weightless here), so the loads of (3) no longer balance: the
// difference would end up on the three constraints below as a spurious
// point force. The base of the box is what carried that weight, so we take
// it off there: a correction to the traction on the bottom edge, linear in
// x, t_y = q0 + q1 (x - x_base), whose force and moment cancel the missing
// weight's exactly. The loads are then self-equilibrated in every stage.
//
// ## Rigid motion
//
// With tractions on the whole boundary the problem is pure Neumann: the
// loads are self-equilibrated, and the stiffness is singular with the three
// rigid motions as its kernel. We pin one vertex of the box (both components)
// and, at the vertex farthest away along the box, the component normal to the
// line joining them: the minimal constraints, which carry no force when the
// loads are in equilibrium. The code measures those reactions after every
// solve (InsituField::reaction_ratio) instead of trusting this. The reported
// displacement then has the rigid motion that best fits the outer boundary
// (least squares over its vertices, weighted by edge length) removed, so
// that "the far field stays put"; strains and stresses do not change.
//
// ## Solvers
//
// Small systems go to UMFPACK. Larger ones to conjugate gradients with
// PETSc's smoothed-aggregation AMG (GAMG), given the three rigid-body modes
// as its near-null space (two translations and the rotation): with only the
// two translations aggregation coarsens elasticity poorly. GAMG rather than
// Trilinos ML, which deal.II also offers: on the 420k-triangle tunnel both
// need 18-19 iterations at the same cost per iteration, but ML's Galerkin
// products claim 350 MB for a moment where GAMG's claim 140 MB, and ML keeps
// 155 MB of hierarchy where GAMG keeps 113 MB. If CG does not converge the
// direct solver takes over and the record says so.
//
// The alphas of one grid share what does not change (update_system,
// solve_amg_cg): the dofs and sparsity, the host rock's part of the matrix
// and loads (only cells whose law changed are assembled again, as the
// difference of their laws), GAMG's hierarchy while CG stays fast with it, and
// CG's start, projected from the earlier solutions. None of it changes the
// answer: CG stops on the residual.
#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/lac/vector_memory.h>
#include <malloc.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <numeric>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "dealii_grid.hpp"
#include "gamg_preconditioner.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/insitu/constants.hpp"
#include "rockfdem/insitu/insitu.hpp"

namespace rockfdem::insitu {

namespace {

using namespace dealii;

// Boundary faces carry the mesh's edge tags as boundary ids (kBottom ...
// kLeft on the box, kExcavation where the core was removed, 0 untagged);
// what the assembly needs is their load kind (grid::FaceLoad).
using grid::kBase;
using grid::kFree;
using grid::kLoaded;
using grid::loaded;

/// What a triangle is during one stage.
enum class Role : std::uint8_t {
  kRock,     ///< host rock: sigma0 + C_rock eps
  kGround,   ///< core, or lining ring not yet installed: alpha (sigma0 + C_core eps)
  kLining,   ///< installed lining: C_lining (eps - eps_install)
  kRemoved,  ///< excavated (alpha = 0): not in the system
};

/// The plane-strain isotropic elasticity tensor
/// C_ijkl = lambda delta_ij delta_kl + mu (delta_ik delta_jl + delta_il delta_jk).
SymmetricTensor<4, 2> elasticity_tensor(const ElasticMaterial& m) {
  const double lambda = m.E * m.nu / ((1 + m.nu) * (1 - 2 * m.nu));
  const double mu = m.E / (2 * (1 + m.nu));
  SymmetricTensor<4, 2> C;
  for (unsigned int i = 0; i < 2; ++i)
    for (unsigned int j = 0; j < 2; ++j)
      for (unsigned int k = 0; k < 2; ++k)
        for (unsigned int l = 0; l < 2; ++l)
          C[i][j][k][l] = (i == j && k == l ? lambda : 0.0) + ((i == k && j == l) ? mu : 0.0) +
                          ((i == l && j == k) ? mu : 0.0);
  return C;
}

double lame_lambda(const ElasticMaterial& m) { return m.E * m.nu / ((1 + m.nu) * (1 - 2 * m.nu)); }

/// The stiffness product and GAMG's cycle as deal.II's solvers call them.
template <class OnArrays>
struct OnVectors {
  const OnArrays& op;
  void vmult(Vector<double>& dst, const Vector<double>& src) const {
    op.apply(src.data(), dst.data());
  }
};

/// The in-situ stage: one elastic solve per softening factor.
class InsituProblem {
 public:
  InsituProblem(const mesh::Mesh& mesh, const InsituSpec& spec);
  std::vector<InsituField> run();

 private:
  void assign_roles(double alpha);
  void make_grid();
  void setup_system();
  void release_system();
  void balance_removed_weight(double alpha);
  void assemble_system(double alpha);
  // The stage a matrix (and the right-hand side assembled with it) holds:
  // the roles and alpha it was last brought to, and the base correction (no
  // roles: nothing assembled yet).
  struct HeldStage {
    std::vector<Role> role;
    double alpha = 1;
    double base_q0 = 0, base_q1 = 0;
  };
  template <class Matrix>
  void update_system(double alpha, Matrix& matrix, HeldStage& held, bool with_loads);
  void add_base_correction(const DoFHandler<2>::active_cell_iterator& cell, double dq0, double dq1,
                           Vector<double>& cell_vector);
  void solve(double alpha, InsituField& field);
  void output_results(double alpha, InsituField& field);

  // The constitutive law of one cell during this stage, see (2) and (3).
  struct CellLaw {
    SymmetricTensor<4, 2> D;
    SymmetricTensor<2, 2> s0;
    Tensor<1, 2> b;
  };
  CellLaw cell_law(int triangle, double alpha, const Point<2>& x) const {
    return cell_law(role_[triangle], triangle, alpha, x);
  }
  CellLaw cell_law(Role role, int triangle, double alpha, const Point<2>& x) const;
  SymmetricTensor<2, 2> initial_stress(const Point<2>& x) const;
  double initial_szz(const Point<2>& x) const;
  Tensor<1, 2> boundary_traction(const Point<2>& x, const Tensor<1, 2>& normal) const;
  void make_direct_matrix();
  void solve_direct();
  int solve_amg_cg(double target_residual, InsituField& field);
  void build_amg();
  void start_from_earlier_solutions();
  void remember_solution();
  template <class CellVector>
  void add_boundary_tractions(const DoFHandler<2>::active_cell_iterator& cell, double sign,
                              CellVector& cell_vector);

  const mesh::Mesh& mesh_;
  const InsituSpec& spec_;

  // Bookkeeping between the mesh record and deal.II's objects.
  std::unordered_set<std::uint64_t> outer_edges_;  ///< edges with one triangle in the full mesh
  std::vector<Role> role_;                         ///< per mesh triangle, this stage
  std::vector<std::uint8_t> grid_removed_;         ///< removal pattern the grid was built for
  bool have_grid_ = false;
  bool have_system_ = false;              ///< dofs and sparsity match the grid
  std::vector<int> cell_to_triangle_;     ///< active cell index -> mesh triangle
  std::vector<int> grid_to_mesh_vertex_;  ///< triangulation vertex -> mesh vertex

  // The finite element machinery of step-8, on simplices.
  Triangulation<2> triangulation_;
  const FESystem<2> fe_;
  const MappingFE<2> mapping_;
  // One point per cell (the centroid) integrates the P1 weak form exactly;
  // three per box edge integrate the traction (see the introduction). The
  // FEValues objects remember the last cell they saw (to skip work on
  // congruent cells), so they are made anew with every new triangulation.
  const QGaussSimplex<2> quadrature_;
  const QGaussSimplex<1> face_quadrature_;
  std::unique_ptr<FEValues<2>> fe_values_;
  std::unique_ptr<FEFaceValues<2>> fe_face_values_;
  DoFHandler<2> dof_handler_;
  AffineConstraints<double> constraints_;
  std::vector<types::global_dof_index> pinned_dofs_;
  SparsityPattern sparsity_pattern_;
  // The stiffness lives in one matrix: deal.II's for UMFPACK, PETSc's for
  // AMG-CG (GAMG reads it, CG multiplies with it). Between alphas only the
  // cells whose law changed are added again (update_system), and GAMG's
  // hierarchy is kept while it still serves (solve_amg_cg). The right-hand
  // side goes along with the matrix: only the changed cells' loads change.
  bool use_cg_ = false;
  SparseMatrix<double> system_matrix_;
  HeldStage direct_held_;
  // Built only with the MPI runtime, which starts PETSc.
  std::unique_ptr<PETScWrappers::SparseMatrix> cg_matrix_;
  HeldStage cg_held_;
  std::unique_ptr<GamgPreconditioner> amg_;
  int amg_reference_iterations_ = 0;  ///< first solve after the last build
  int last_iterations_ = 0;
  Vector<double> solution_;
  // This grid's earlier solutions, orthonormalised: CG starts from the
  // combination of them closest to the new solution (see
  // start_from_earlier_solutions).
  std::vector<Vector<double>> earlier_solutions_;
  Vector<double> system_rhs_;
  Vector<double> insitu_forces_;  ///< int sigma0 : eps(phi_i): the load scale

  // The base correction for removed weight (gravity only), see above.
  double base_q0_ = 0, base_q1_ = 0, base_x_ = 0;

  // Materials and the staged state.
  SymmetricTensor<4, 2> C_rock_, C_core_, C_lining_;
  bool lining_installed_ = false;
  // Held only when a lining goes in, and only for its triangles (the rest
  // of the mesh never reads them: 48 B per triangle otherwise).
  std::vector<int> lining_slot_;                     ///< per mesh triangle: its row below, or -1
  std::vector<SymmetricTensor<2, 2>> eps_previous_;  ///< end of the last stage
  std::vector<SymmetricTensor<2, 2>> eps_install_;   ///< at the lining's install
};

// Rows for the lining's triangles in mesh order; none without a lining.
std::vector<int> lining_slots(const mesh::Mesh& mesh, bool lining) {
  std::vector<int> slot(lining ? mesh.n_triangles() : 0, -1);
  int rows = 0;
  for (std::size_t t = 0; t < slot.size(); ++t)
    if (mesh.zone[t] == mesh::kLining) slot[t] = rows++;
  return slot;
}

std::size_t count_rows(const std::vector<int>& slot) {
  std::size_t n = 0;
  for (const int s : slot) n += s >= 0;
  return n;
}

// ---------------------------------------------------------------------------
// Construction: the materials and the outer boundary of the full mesh.
// ---------------------------------------------------------------------------

InsituProblem::InsituProblem(const mesh::Mesh& mesh, const InsituSpec& spec)
    : mesh_(mesh),
      spec_(spec),
      fe_(FE_SimplexP<2>(1), 2),
      mapping_(FE_SimplexP<2>(1)),
      quadrature_(1),
      face_quadrature_(3),
      lining_slot_(lining_slots(mesh, spec.lining.active)),
      eps_previous_(count_rows(lining_slot_)),
      eps_install_(eps_previous_.size()) {
  // validate() has made sure every material a stage needs is present.
  if (spec.materials.rock) C_rock_ = elasticity_tensor(*spec.materials.rock);
  if (spec.materials.core) C_core_ = elasticity_tensor(*spec.materials.core);
  if (spec.materials.lining) C_lining_ = elasticity_tensor(*spec.materials.lining);

  // Only the edges of the full mesh's outer boundary carry the far-field
  // traction, in every stage.
  outer_edges_ = grid::outer_edges(mesh);
}

// A field InsituSpec::keep_fields does not name keeps its report only.
bool keeps_field(const InsituSpec& spec, double alpha) {
  const auto& k = spec.keep_fields;
  return k.empty() || std::find(k.begin(), k.end(), alpha) != k.end();
}

void drop_arrays(InsituField& f) {
  std::vector<Stress>().swap(f.stress);
  std::vector<std::uint8_t>().swap(f.active);
  std::vector<double>().swap(f.ux);
  std::vector<double>().swap(f.uy);
}

// ---------------------------------------------------------------------------
// run(): the staged loop of step-18, one elastic solve per alpha.
// ---------------------------------------------------------------------------

std::vector<InsituField> InsituProblem::run() {
  std::vector<InsituField> fields;
  for (const double alpha : spec_.alphas) {
    InsituField field;
    field.alpha = alpha;
    Timer timer;

    // The lining goes in at the first stage with alpha <= install_alpha,
    // stress-free on the ground as the previous stage left it.
    if (spec_.lining.active && !lining_installed_ && alpha <= spec_.lining.install_alpha) {
      lining_installed_ = true;
      eps_install_ = eps_previous_;  // both hold the lining's triangles alone
    }
    field.lining_installed = lining_installed_;

    assign_roles(alpha);
    make_grid();  // rebuilds only when the set of removed cells changed
    setup_system();
    field.setup_seconds = timer.wall_time();

    timer.restart();
    balance_removed_weight(alpha);
    assemble_system(alpha);
    field.assembly_seconds = timer.wall_time();

    timer.restart();
    solve(alpha, field);
    field.solve_seconds = timer.wall_time();

    timer.restart();
    output_results(alpha, field);
    field.postprocess_seconds = timer.wall_time();
    field.total_seconds = field.setup_seconds + field.assembly_seconds + field.solve_seconds +
                          field.postprocess_seconds;
    if (spec_.on_field) spec_.on_field(field);
    if (!keeps_field(spec_, alpha)) drop_arrays(field);
    fields.push_back(std::move(field));
  }
  return fields;
}

// ---------------------------------------------------------------------------
// Roles and the triangulation.
// ---------------------------------------------------------------------------

void InsituProblem::assign_roles(const double alpha) {
  role_.resize(mesh_.n_triangles());
  for (std::size_t t = 0; t < mesh_.n_triangles(); ++t) {
    switch (mesh_.zone[t]) {
      case mesh::kRock:
        role_[t] = Role::kRock;
        break;
      case mesh::kLining:
        if (lining_installed_) {
          role_[t] = Role::kLining;
          break;
        }
        [[fallthrough]];  // not installed: ground still to be excavated
      default:
        role_[t] = alpha > 0 ? Role::kGround : Role::kRemoved;
    }
  }
}

// The triangulation for this stage's removal pattern (grid::build_triangulation).
void InsituProblem::make_grid() {
  std::vector<std::uint8_t> removed(mesh_.n_triangles());
  for (std::size_t t = 0; t < mesh_.n_triangles(); ++t) removed[t] = role_[t] == Role::kRemoved;
  if (have_grid_ && removed == grid_removed_) return;

  // The old grid's system goes first, so that the new grid is built in the
  // space the matrix and GAMG's hierarchy gave back, not above them.
  release_system();
  fe_values_.reset();
  fe_face_values_.reset();
  dof_handler_.clear();
  grid::GridMap map = grid::build_triangulation(mesh_, removed, outer_edges_, triangulation_);
  cell_to_triangle_ = std::move(map.cell_to_triangle);
  grid_to_mesh_vertex_ = std::move(map.grid_to_mesh_vertex);
  grid_removed_ = std::move(removed);
  have_grid_ = true;
  have_system_ = false;
}

// ---------------------------------------------------------------------------
// setup_system(): dofs, the three rigid-motion constraints, the sparsity.
// ---------------------------------------------------------------------------

void InsituProblem::release_system() {
  amg_.reset();            // GAMG reads the matrix: the hierarchy goes first
  system_matrix_.clear();  // it holds a pointer to the pattern we replace
  cg_matrix_.reset();
  earlier_solutions_.clear();
  direct_held_ = HeldStage();
  cg_held_ = HeldStage();
}

void InsituProblem::setup_system() {
  if (have_system_) return;
  release_system();
  dof_handler_.reinit(triangulation_);
  dof_handler_.distribute_dofs(fe_);

  pinned_dofs_ = grid::rigid_motion_pins(dof_handler_);
  constraints_.clear();
  for (const auto dof : pinned_dofs_) constraints_.add_line(dof);
  constraints_.close();

  // The matrix the solver needs, and only that one (PETSc keeps its own
  // copy of the pattern: deal.II's is made only for UMFPACK).
  const SolverSpec& s = spec_.solver;
  const bool small = dof_handler_.n_dofs() < s.direct_below_dofs;
  const bool want_cg = s.kind == LinearSolver::kAmgCg || (s.kind == LinearSolver::kAuto && !small);
  use_cg_ = want_cg && ScopedParallelInit::active();
  sparsity_pattern_.reinit(0, 0, 0);
  if (use_cg_) {
    DynamicSparsityPattern dsp(dof_handler_.n_dofs(), dof_handler_.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler_, dsp, constraints_, false);
    cg_matrix_ = std::make_unique<PETScWrappers::SparseMatrix>(dsp);
  } else {
    make_direct_matrix();
  }
  solution_.reinit(dof_handler_.n_dofs());
  system_rhs_.reinit(dof_handler_.n_dofs());
  insitu_forces_.reinit(dof_handler_.n_dofs());
  fe_values_ = std::make_unique<FEValues<2>>(
      mapping_, fe_, quadrature_,
      update_values | update_gradients | update_quadrature_points | update_JxW_values);
  fe_face_values_ = std::make_unique<FEFaceValues<2>>(
      mapping_, fe_, face_quadrature_,
      update_values | update_quadrature_points | update_normal_vectors | update_JxW_values);
  have_system_ = true;
}

// ---------------------------------------------------------------------------
// The in-situ state and the loads.
// ---------------------------------------------------------------------------

SymmetricTensor<2, 2> InsituProblem::initial_stress(const Point<2>& x) const {
  return grid::initial_stress(spec_, x);
}

double InsituProblem::initial_szz(const Point<2>& x) const { return grid::initial_szz(spec_, x); }

Tensor<1, 2> InsituProblem::boundary_traction(const Point<2>& x, const Tensor<1, 2>& normal) const {
  SymmetricTensor<2, 2> sigma;
  if (spec_.loading == BoundaryLoading::kKirschExact) {
    KirschCase k;
    k.a = spec_.kirsch_radius;
    k.sH = spec_.far_field.sH;
    k.sV = spec_.far_field.sV;
    k.angle_deg = spec_.far_field.angle_deg;
    const Stress s = kirsch_stress(k, x[0], x[1]);
    sigma[0][0] = s.sxx;
    sigma[1][1] = s.syy;
    sigma[0][1] = s.sxy;
  } else {
    sigma = initial_stress(x);
  }
  return sigma * normal;
}

InsituProblem::CellLaw InsituProblem::cell_law(const Role role, const int triangle,
                                               const double alpha, const Point<2>& x) const {
  Tensor<1, 2> gravity;
  gravity[1] = -spec_.gravity.unit_weight;
  switch (role) {
    case Role::kRock:
      return {C_rock_, initial_stress(x), gravity};
    case Role::kGround:
      return {alpha * C_core_, alpha * initial_stress(x), alpha * gravity};
    case Role::kLining:
      // The lining's weight is not part of the in-situ stage.
      return {C_lining_, -(C_lining_ * eps_install_[lining_slot_[triangle]]), Tensor<1, 2>()};
    case Role::kRemoved:
      break;  // carries nothing (and holds nothing in a matrix not yet assembled)
  }
  return {};
}

template <class CellVector>
void InsituProblem::add_boundary_tractions(const DoFHandler<2>::active_cell_iterator& cell,
                                           const double sign, CellVector& cell_vector) {
  FEFaceValues<2>& fe_face_values = *fe_face_values_;
  const FEValuesExtractors::Vector displacement(0);
  for (const unsigned int f : cell->face_indices()) {
    if (!loaded(cell->face(f))) continue;
    const bool base = cell->face(f)->user_index() == kBase;
    fe_face_values.reinit(cell, f);
    for (const unsigned int q : fe_face_values.quadrature_point_indices()) {
      const Point<2>& x = fe_face_values.quadrature_point(q);
      Tensor<1, 2> t = boundary_traction(x, fe_face_values.normal_vector(q));
      if (base) t[1] += base_q0_ + base_q1_ * (x[0] - base_x_);
      for (const unsigned int i : fe_face_values.dof_indices())
        cell_vector(i) +=
            sign * (fe_face_values[displacement].value(i, q) * t) * fe_face_values.JxW(q);
    }
  }
}

// The change of the base correction alone, on the base faces of a cell
// (the rest of the box traction does not change between stages).
void InsituProblem::add_base_correction(const DoFHandler<2>::active_cell_iterator& cell,
                                        const double dq0, const double dq1,
                                        Vector<double>& cell_vector) {
  FEFaceValues<2>& fe_face_values = *fe_face_values_;
  const FEValuesExtractors::Vector displacement(0);
  for (const unsigned int f : cell->face_indices()) {
    if (!cell->face(f)->at_boundary() || cell->face(f)->user_index() != kBase) continue;
    fe_face_values.reinit(cell, f);
    for (const unsigned int q : fe_face_values.quadrature_point_indices()) {
      Tensor<1, 2> t;
      t[1] = dq0 + dq1 * (fe_face_values.quadrature_point(q)[0] - base_x_);
      for (const unsigned int i : fe_face_values.dof_indices())
        cell_vector(i) += (fe_face_values[displacement].value(i, q) * t) * fe_face_values.JxW(q);
    }
  }
}

// The weight that left with the softened or removed core (and the ring, once
// the weightless lining replaces it): force F and moment M about z of the
// missing body force, from the mesh record (removed cells are not in the
// triangulation). The base traction t_y = q0 + q1 (x - x_base) with
// int t_y = -F and int t_y x = -M puts the balance back.
void InsituProblem::balance_removed_weight(const double alpha) {
  base_q0_ = base_q1_ = base_x_ = 0;
  const double gamma = spec_.gravity.unit_weight;
  if (gamma == 0) return;
  double F = 0, M = 0;  // the change of the vertical body force, b_cell - b0
  for (std::size_t t = 0; t < mesh_.n_triangles(); ++t) {
    double kept = 1;  // fraction of the in-situ weight still acting
    switch (role_[t]) {
      case Role::kRock:
        kept = 1;
        break;
      case Role::kGround:
        kept = alpha;
        break;
      case Role::kLining:
      case Role::kRemoved:
        kept = 0;
        break;
    }
    if (kept == 1) continue;
    const auto& tri = mesh_.triangles[t];
    const double xa = mesh_.x[tri[0]], ya = mesh_.y[tri[0]], xb = mesh_.x[tri[1]],
                 yb = mesh_.y[tri[1]], xc = mesh_.x[tri[2]], yc = mesh_.y[tri[2]];
    const double area = 0.5 * ((xb - xa) * (yc - ya) - (xc - xa) * (yb - ya));
    const double dF = (1 - kept) * gamma * area;  // weight gone: the load rises by this
    F += dF;
    M += dF * (xa + xb + xc) / 3;
  }
  if (F == 0) return;

  const grid::BaseMoments base = grid::base_moments(triangulation_, "insitu");
  base_x_ = base.x;
  base_q0_ = -F / base.length;
  base_q1_ = base.inertia > 0 ? (-M + F * base_x_) / base.inertia : 0;
}

// ---------------------------------------------------------------------------
// assemble_system(): the weak form (3), cell by cell as in step-8.
// ---------------------------------------------------------------------------

void InsituProblem::assemble_system(const double alpha) {
  if (use_cg_)
    update_system(alpha, *cg_matrix_, cg_held_, true);
  else
    update_system(alpha, system_matrix_, direct_held_, true);
}

// The weak form (3) is linear in each cell's law (D, s0, b), so bringing the
// matrix and right-hand side from the stage they hold to this one means
// adding, cell by cell, the terms of law_now - law_held, and only on the
// cells whose law changed: the softened core at every alpha, the ring when
// the lining goes in. The host rock, most of the grid, and the box
// tractions are assembled once per grid; of the loads only the base
// correction (gravity) changes besides. A system that holds nothing gets
// every cell, and the in-situ nodal forces that scale the tolerances.
// (The rows of the pinned dofs only get a positive diagonal and a zero
// right-hand side.)
template <class Matrix>
void InsituProblem::update_system(const double alpha, Matrix& matrix, HeldStage& held,
                                  const bool with_loads) {
  const bool empty = held.role.empty();
  if (empty && with_loads) {
    system_rhs_ = 0;
    insitu_forces_ = 0;
  }
  const double dq0 = base_q0_ - (empty ? 0.0 : held.base_q0);
  const double dq1 = base_q1_ - (empty ? 0.0 : held.base_q1);
  const bool base_changed = with_loads && !empty && (dq0 != 0 || dq1 != 0);

  FEValues<2>& fe_values = *fe_values_;
  const FEValuesExtractors::Vector displacement(0);
  const unsigned int dofs_per_cell = fe_.n_dofs_per_cell();
  FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell);
  Vector<double> cell_rhs(dofs_per_cell);
  Vector<double> cell_insitu(dofs_per_cell);
  std::vector<types::global_dof_index> local_dof_indices(dofs_per_cell);
  std::vector<SymmetricTensor<2, 2>> eps_phi(dofs_per_cell);

  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    const int t = cell_to_triangle_[cell->active_cell_index()];
    const Role held_role = empty ? Role::kRemoved : held.role[t];
    const bool changed =
        held_role != role_[t] || (role_[t] == Role::kGround && held.alpha != alpha);
    if (!changed) {
      if (!base_changed || !cell->at_boundary()) continue;
      cell_rhs = 0;
      add_base_correction(cell, dq0, dq1, cell_rhs);
      cell->get_dof_indices(local_dof_indices);
      constraints_.distribute_local_to_global(cell_rhs, local_dof_indices, system_rhs_);
      continue;
    }
    fe_values.reinit(cell);
    cell_matrix = 0;
    cell_rhs = 0;
    cell_insitu = 0;
    for (const unsigned int q : fe_values.quadrature_point_indices()) {
      const Point<2>& x = fe_values.quadrature_point(q);
      const CellLaw now = cell_law(t, alpha, x);
      const CellLaw before = cell_law(held_role, t, held.alpha, x);
      const SymmetricTensor<4, 2> D = now.D - before.D;
      const SymmetricTensor<2, 2> s0 = now.s0 - before.s0;
      const Tensor<1, 2> b = now.b - before.b;
      const SymmetricTensor<2, 2> sigma0 = initial_stress(x);
      const double JxW = fe_values.JxW(q);
      for (const unsigned int i : fe_values.dof_indices())
        eps_phi[i] = fe_values[displacement].symmetric_gradient(i, q);
      for (const unsigned int i : fe_values.dof_indices()) {
        const SymmetricTensor<2, 2> D_eps_i = D * eps_phi[i];
        for (const unsigned int j : fe_values.dof_indices())
          cell_matrix(i, j) += (D_eps_i * eps_phi[j]) * JxW;
        cell_rhs(i) += (fe_values[displacement].value(i, q) * b - eps_phi[i] * s0) * JxW;
        cell_insitu(i) += (eps_phi[i] * sigma0) * JxW;
      }
    }
    if (empty)
      add_boundary_tractions(cell, +1.0, cell_rhs);
    else if (base_changed)
      add_base_correction(cell, dq0, dq1, cell_rhs);

    cell->get_dof_indices(local_dof_indices);
    if (!with_loads) {
      constraints_.distribute_local_to_global(cell_matrix, local_dof_indices, matrix);
      continue;
    }
    constraints_.distribute_local_to_global(cell_matrix, cell_rhs, local_dof_indices, matrix,
                                            system_rhs_);
    if (empty) insitu_forces_.add(local_dof_indices, cell_insitu);
  }
  if constexpr (std::is_same_v<Matrix, PETScWrappers::SparseMatrix>)
    matrix.compress(VectorOperation::add);
  held.role = role_;
  held.alpha = alpha;
  held.base_q0 = base_q0_;
  held.base_q1 = base_q1_;
}

// ---------------------------------------------------------------------------
// solve(): AMG-CG or UMFPACK, with the fallback.
// ---------------------------------------------------------------------------

void InsituProblem::solve(const double alpha, InsituField& field) {
  field.n_dofs = dof_handler_.n_dofs();
  field.n_cells = triangulation_.n_active_cells();

  // CG stops at an absolute residual scaled by the in-situ nodal forces, not
  // by the right-hand side: at alpha = 1 the latter is round-off, and nothing
  // is to be gained by reducing it further. The test is on the residual, so
  // where CG starts (the previous alpha's solution) does not change what it
  // delivers.
  const double target = spec_.solver.tolerance * insitu_forces_.l2_norm();

  if (!use_cg_) {
    const bool wanted_cg = spec_.solver.kind == LinearSolver::kAmgCg ||
                           (spec_.solver.kind == LinearSolver::kAuto &&
                            field.n_dofs >= spec_.solver.direct_below_dofs);
    field.solver =
        wanted_cg ? "direct (no MPI runtime: create ScopedParallelInit in main for AMG)" : "direct";
    solve_direct();
  } else {
    try {
      field.iterations = solve_amg_cg(target, field);
      field.solver = "amg-cg";
    } catch (const SolverControl::NoConvergence& e) {
      field.iterations = static_cast<int>(e.last_step);
      field.solver = "direct (cg stopped at " + std::to_string(e.last_step) + " iterations)";
      amg_.reset();
      // UMFPACK takes deal.II's matrix: assembled for this alpha only.
      make_direct_matrix();
      HeldStage held;
      update_system(alpha, system_matrix_, held, false);
      solve_direct();
      system_matrix_.clear();
      sparsity_pattern_.reinit(0, 0, 0);
    }
  }
  constraints_.distribute(solution_);
}

void InsituProblem::make_direct_matrix() {
  DynamicSparsityPattern dsp(dof_handler_.n_dofs(), dof_handler_.n_dofs());
  DoFTools::make_sparsity_pattern(dof_handler_, dsp, constraints_, false);
  sparsity_pattern_.copy_from(dsp);
  system_matrix_.reinit(sparsity_pattern_);
}

void InsituProblem::solve_direct() { grid::solve_direct(system_matrix_, solution_, system_rhs_); }

// GAMG's hierarchy is built on the first matrix of a grid and kept for the
// alphas after it: the preconditioner only sets how fast CG converges, never
// what it converges to, and the matrices of neighbouring alphas differ in the
// core only. It is built again when CG has slowed down to more than
// kRebuildGrowth times the iterations it needed right after the last build,
// or when a solve with the kept hierarchy does not converge. The kept
// hierarchy's finest level works with this alpha's matrix (the same PETSc
// object, its values changed), its coarse levels are the build's.
int InsituProblem::solve_amg_cg(const double target_residual, InsituField& field) {
  constexpr double kRebuildGrowth = 1.5;
  const bool slowed = amg_reference_iterations_ > 0 &&
                      last_iterations_ > kRebuildGrowth * amg_reference_iterations_;
  start_from_earlier_solutions();

  // Nothing to solve (alpha = 1: the right-hand side is round-off): no
  // hierarchy is built for it.
  const PetscProduct product(*cg_matrix_);
  const OnVectors<PetscProduct> stiffness{product};
  const auto start_residual = [&] {  // its vector is gone before GAMG's set-up
    Vector<double> residual(solution_.size());
    stiffness.vmult(residual, solution_);
    residual.sadd(-1.0, 1.0, system_rhs_);
    return residual.l2_norm();
  };
  if (start_residual() <= target_residual) return 0;

  const auto build = [&] {
    Timer timer;
    build_amg();
    field.preconditioner_seconds += timer.wall_time();
  };
  field.preconditioner_reused = amg_ && !slowed;
  if (!field.preconditioner_reused) build();

  const auto run_cg = [&] {
    SolverControl control(spec_.solver.max_iterations, target_residual, false, false);
    SolverCG<Vector<double>> cg(control);
    cg.solve(stiffness, solution_, system_rhs_, OnVectors<GamgPreconditioner>{*amg_});
    // deal.II's pool keeps CG's vectors for the next solve: they would sit
    // under the next alpha's set-up (3 vectors, 10 MB at 420k triangles).
    // Safe because no pooled vector outlives cg.solve (SolverCG's are its own).
    GrowingVectorMemory<Vector<double>>::release_unused_memory();
    return static_cast<int>(control.last_step());
  };
  int iterations = 0;
  try {
    iterations = run_cg();
  } catch (const SolverControl::NoConvergence&) {
    if (!field.preconditioner_reused) throw;
    field.preconditioner_reused = false;
    build();
    iterations = run_cg();
  }
  if (amg_reference_iterations_ == 0) amg_reference_iterations_ = iterations;
  last_iterations_ = iterations;
  remember_solution();
  return iterations;
}

// CG's start: the combination of this grid's earlier solutions closest to
// the new one in the energy norm, i.e. the Galerkin projection of
// K u = f onto their span (m products with K and an m x m solve, m <= the
// number of alphas so far). The fields are smooth in alpha, so a few of
// them span most of the next one; the previous solution alone is the
// crudest member of that span. Only the start changes: CG's stopping test
// is on the residual.
void InsituProblem::start_from_earlier_solutions() {
  const std::size_t m = earlier_solutions_.size();
  if (m == 0) return;
  FullMatrix<double> G(m, m);
  Vector<double> g(m), K_w(solution_.size());
  const PetscProduct stiffness(*cg_matrix_);
  for (std::size_t i = 0; i < m; ++i) {
    stiffness.apply(earlier_solutions_[i].data(), K_w.data());
    for (std::size_t j = 0; j < m; ++j) G(j, i) = earlier_solutions_[j] * K_w;
    g(i) = earlier_solutions_[i] * system_rhs_;
  }
  G.gauss_jordan();
  Vector<double> c(m);
  G.vmult(c, g);
  solution_ = 0;
  for (std::size_t i = 0; i < m; ++i) solution_.add(c(i), earlier_solutions_[i]);
}

// Adds this solution's new direction to the basis (Gram-Schmidt, twice for
// round-off); a solution the basis already spans adds nothing.
void InsituProblem::remember_solution() {
  constexpr std::size_t kMaxBasis = 8;
  const double norm = solution_.l2_norm();
  if (norm == 0) return;
  Vector<double> w = solution_;
  for (int pass = 0; pass < 2; ++pass)
    for (const Vector<double>& b : earlier_solutions_) w.add(-(w * b), b);
  const double rest = w.l2_norm();
  if (rest <= 1e-8 * norm) return;
  w /= rest;
  if (earlier_solutions_.size() == kMaxBasis) earlier_solutions_.erase(earlier_solutions_.begin());
  earlier_solutions_.push_back(std::move(w));
}

void InsituProblem::build_amg() {
  // The near-null space: the rigid motions of the plate, evaluated at every
  // vertex dof, in dof order.
  const std::size_t n = dof_handler_.n_dofs();
  std::array<std::vector<double>, 3> modes;
  for (auto& mode : modes) mode.assign(n, 0.0);
  Point<2> center;
  double extent = 0;
  for (const auto& v : triangulation_.get_vertices()) center += v / triangulation_.n_vertices();
  for (const auto& v : triangulation_.get_vertices())
    extent = std::max(extent, (v - center).norm());
  bool node_blocks = true;  // x and y dofs of a vertex next to each other?
  for (const auto& cell : dof_handler_.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices()) {
      const auto dx = cell->vertex_dof_index(v, 0), dy = cell->vertex_dof_index(v, 1);
      const Tensor<1, 2> p = (cell->vertex(v) - center) / extent;
      modes[0][dx] = 1;
      modes[1][dy] = 1;
      modes[2][dx] = -p[1];
      modes[2][dy] = p[0];
      node_blocks = node_blocks && dx % 2 == 0 && dy == dx + 1;
    }
  // GAMG aggregates vertices (blocks of two dofs): P1's dofs come so.
  AssertThrow(node_blocks, ExcMessage("insitu: the dofs of a vertex are not consecutive"));

  // The old hierarchy goes, and the heap it and the earlier solves freed
  // goes back to the system before GAMG's products claim about 140 MB at
  // 420k triangles for a moment: freed but fragmented, it would stay
  // resident and the build would add to it.
  amg_.reset();
  malloc_trim(0);
  amg_ = std::make_unique<GamgPreconditioner>(*cg_matrix_, modes);
  amg_reference_iterations_ = 0;
  last_iterations_ = 0;
}

// ---------------------------------------------------------------------------
// output_results(): stresses per triangle, displacements per vertex, and the
// equilibrium check, all handed back in the mesh's own order.
// ---------------------------------------------------------------------------

void InsituProblem::output_results(const double alpha, InsituField& field) {
  const std::size_t n_t = mesh_.n_triangles(), n_v = mesh_.n_vertices();
  field.stress.assign(n_t, Stress{});
  field.active.assign(n_t, 0);
  field.ux.assign(n_v, 0.0);
  field.uy.assign(n_v, 0.0);

  FEValues<2>& fe_values = *fe_values_;
  const FEValuesExtractors::Vector displacement(0);
  std::vector<SymmetricTensor<2, 2>> eps_q(quadrature_.size());
  std::vector<types::global_dof_index> local_dof_indices(fe_.n_dofs_per_cell());
  Vector<double> cell_residual(fe_.n_dofs_per_cell());
  Vector<double> residual(dof_handler_.n_dofs());

  // 1. Stress per triangle, sigma = s0 + D eps(u) of (2), and the residual
  //    of (3) with the constraints left out: at free dofs it is what the
  //    solver left over, at the pinned dofs it is the reaction.
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    fe_values.reinit(cell);
    fe_values[displacement].get_function_symmetric_gradients(solution_, eps_q);
    const int t = cell_to_triangle_[cell->active_cell_index()];
    const Point<2>& x = fe_values.quadrature_point(0);
    const CellLaw law = cell_law(t, alpha, x);
    const SymmetricTensor<2, 2> sigma = law.s0 + law.D * eps_q[0];

    Stress& out = field.stress[t];
    out.sxx = sigma[0][0];
    out.syy = sigma[1][1];
    out.sxy = sigma[0][1];
    // Plane strain: the out-of-plane stress responds with lambda tr(eps).
    switch (role_[t]) {
      case Role::kRock:
        out.szz = initial_szz(x) + lame_lambda(*spec_.materials.rock) * trace(eps_q[0]);
        break;
      case Role::kGround:
        out.szz = alpha * (initial_szz(x) + lame_lambda(*spec_.materials.core) * trace(eps_q[0]));
        break;
      case Role::kLining:
        out.szz =
            lame_lambda(*spec_.materials.lining) * trace(eps_q[0] - eps_install_[lining_slot_[t]]);
        break;
      case Role::kRemoved:
        break;
    }
    field.active[t] = 1;
    if (!lining_slot_.empty() && lining_slot_[t] >= 0) eps_previous_[lining_slot_[t]] = eps_q[0];

    cell_residual = 0;
    for (const unsigned int i : fe_values.dof_indices())
      cell_residual(i) += (fe_values[displacement].symmetric_gradient(i, 0) * sigma -
                           fe_values[displacement].value(i, 0) * law.b) *
                          fe_values.JxW(0);
    add_boundary_tractions(cell, -1.0, cell_residual);
    cell->get_dof_indices(local_dof_indices);
    residual.add(local_dof_indices, cell_residual);
  }
  const double scale = std::max(insitu_forces_.l2_norm(), 1e-300);
  double reaction = 0;
  for (const auto dof : pinned_dofs_) {
    reaction = std::max(reaction, std::abs(residual(dof)));
    residual(dof) = 0;
  }
  field.reaction_ratio = reaction / scale;
  field.unbalanced_ratio = residual.l2_norm() / scale;

  // 2. Displacement per vertex, less the rigid motion (see the introduction).
  grid::displacement_without_rigid_motion(dof_handler_, solution_, grid_to_mesh_vertex_, field.ux,
                                          field.uy);

  // A solve that left the body far from equilibrium is a numerical failure,
  // not a result.
  const double allowed = std::max(1e-6, 100 * spec_.solver.tolerance);
  if (!(field.unbalanced_ratio <= allowed))
    throw NumericalError(
        "insitu: alpha = " + std::to_string(alpha) + ": the solution is out of balance by " +
        std::to_string(field.unbalanced_ratio) + " of the in-situ nodal forces (allowed " +
        std::to_string(allowed) + "); solver: " + field.solver);
}

}  // namespace

namespace grid {

using namespace dealii;

std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return (hi << 32) | lo;
}

// An edge is on the outer boundary when exactly one triangle of the full
// mesh has it; the excavation boundary has two (rock outside, core inside).
std::unordered_set<std::uint64_t> outer_edges(const mesh::Mesh& mesh) {
  std::unordered_set<std::uint64_t> outer, seen;
  seen.reserve(3 * mesh.n_triangles());
  outer.reserve(mesh.n_triangles() / 4 + 16);
  for (const auto& tri : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t key = edge_key(tri[k], tri[(k + 1) % 3]);
      if (seen.insert(key).second)
        outer.insert(key);
      else
        outer.erase(key);
    }
  return outer;
}

// The triangulation is built directly from the mesh record (no file round
// trip): vertices used by the cells that stay, renumbered compactly, and one
// CellData per triangle with its zone as material id. The cells keep the
// record's order, which lets every result go back to its triangle; we check
// that rather than assume it.
GridMap build_triangulation(const mesh::Mesh& mesh, const std::vector<std::uint8_t>& removed,
                            const std::unordered_set<std::uint64_t>& outer,
                            Triangulation<2>& triangulation) {
  GridMap map;
  std::vector<int> mesh_to_grid(mesh.n_vertices(), -1);
  map.grid_to_mesh_vertex.clear();
  std::vector<Point<2>> vertices;
  std::vector<CellData<2>> cells;
  std::vector<int> cell_triangles;
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    if (removed[t]) continue;
    CellData<2> cell(3);
    for (unsigned int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[t][k];
      if (mesh_to_grid[v] < 0) {
        mesh_to_grid[v] = static_cast<int>(vertices.size());
        vertices.emplace_back(mesh.x[v], mesh.y[v]);
        map.grid_to_mesh_vertex.push_back(v);
      }
      cell.vertices[k] = mesh_to_grid[v];
    }
    cell.material_id = static_cast<types::material_id>(mesh.zone[t]);
    cells.push_back(cell);
    cell_triangles.push_back(static_cast<int>(t));
  }
  if (cells.empty())
    throw InputError("insitu: every triangle is removed at alpha = 0: the system is singular");

  // The cells that stay must hang together, or some part floats free and
  // the stiffness is singular (three constraints hold one body only).
  std::vector<int> parent(vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&parent](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const auto& c : cells)
    for (int k = 1; k < 3; ++k) parent[find(c.vertices[k])] = find(c.vertices[0]);
  std::size_t n_parts = 0;
  for (std::size_t v = 0; v < vertices.size(); ++v)
    n_parts += find(static_cast<int>(v)) == static_cast<int>(v);
  if (n_parts != 1)
    throw InputError("insitu: the cells left in the system form " + std::to_string(n_parts) +
                     " disconnected parts: the system is singular (a zone floats free once "
                     "the core is removed; check the zones or keep alpha > 0)");

  triangulation.clear();
  triangulation.create_triangulation(vertices, cells, SubCellData());

  // Map cells back to triangles: the creation order if deal.II kept it (it
  // does in 9.4), a search by vertex triple otherwise.
  map.cell_to_triangle.assign(triangulation.n_active_cells(), -1);
  const auto sorted_vertices = [](std::array<unsigned int, 3> v) {
    std::sort(v.begin(), v.end());
    return v;
  };
  bool same_order = true;
  for (const auto& cell : triangulation.active_cell_iterators()) {
    const auto i = cell->active_cell_index();
    const auto& c = cells[i];
    same_order = same_order && sorted_vertices({cell->vertex_index(0), cell->vertex_index(1),
                                                cell->vertex_index(2)}) ==
                                   sorted_vertices({c.vertices[0], c.vertices[1], c.vertices[2]});
    map.cell_to_triangle[i] = cell_triangles[i];
  }
  if (!same_order) {
    std::map<std::array<unsigned int, 3>, int> by_vertices;
    for (std::size_t i = 0; i < cells.size(); ++i)
      by_vertices[sorted_vertices(
          {cells[i].vertices[0], cells[i].vertices[1], cells[i].vertices[2]})] = cell_triangles[i];
    for (const auto& cell : triangulation.active_cell_iterators())
      map.cell_to_triangle[cell->active_cell_index()] = by_vertices.at(
          sorted_vertices({cell->vertex_index(0), cell->vertex_index(1), cell->vertex_index(2)}));
  }

  // Boundary ids from the mesh's tags; the load kind (see FaceLoad) from
  // the full mesh's outer boundary, the base being its part at the lowest y.
  std::unordered_map<std::uint64_t, int> tags;
  for (const auto& e : mesh.edges) tags[edge_key(e.a, e.b)] = e.tag;
  double y_min = mesh.y[0];
  for (const double y : mesh.y) y_min = std::min(y_min, y);
  double extent = 0;
  for (const auto& p : vertices) extent = std::max(extent, (p - vertices[0]).norm());
  for (const auto& cell : triangulation.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary()) {
        const auto face = cell->face(f);
        const int a = map.grid_to_mesh_vertex[face->vertex_index(0)];
        const int b = map.grid_to_mesh_vertex[face->vertex_index(1)];
        const auto tag = tags.find(edge_key(a, b));
        face->set_boundary_id(tag != tags.end() && tag->second > 0 && tag->second < 255
                                  ? static_cast<types::boundary_id>(tag->second)
                                  : 0);
        FaceLoad load = kFree;
        if (outer.count(edge_key(a, b))) {
          const bool base = std::abs(mesh.y[a] - y_min) < 1e-12 * extent &&
                            std::abs(mesh.y[b] - y_min) < 1e-12 * extent;
          load = base ? kBase : kLoaded;
        }
        face->set_user_index(load);
      }

  return map;
}

std::vector<types::global_dof_index> rigid_motion_pins(const DoFHandler<2>& dof_handler) {
  // Pin the loaded-boundary vertex with the smallest x (both components), and
  // at the one with the largest x the component normal to the line joining
  // them. Without a loaded boundary (a mesh with no box), any two vertices.
  const auto& verts = dof_handler.get_triangulation().get_vertices();
  unsigned int a = 0, b = 0;
  bool found = false;
  for (const auto& cell : dof_handler.get_triangulation().active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (loaded(cell->face(f)))
        for (unsigned int k = 0; k < 2; ++k) {
          const unsigned int v = cell->face(f)->vertex_index(k);
          if (!found) a = b = v, found = true;
          if (verts[v][0] < verts[a][0]) a = v;
          if (verts[v][0] > verts[b][0]) b = v;
        }
  if (!found || a == b) {
    a = 0;
    b = 0;
    for (unsigned int v = 0; v < verts.size(); ++v)
      if ((verts[v] - verts[0]).norm() > (verts[b] - verts[0]).norm()) b = v;
  }
  const unsigned int b_component =
      std::abs(verts[b][0] - verts[a][0]) >= std::abs(verts[b][1] - verts[a][1]) ? 1 : 0;

  std::vector<types::global_dof_index> pins(3, numbers::invalid_dof_index);
  for (const auto& cell : dof_handler.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices()) {
      if (cell->vertex_index(v) == a) {
        pins[0] = cell->vertex_dof_index(v, 0);
        pins[1] = cell->vertex_dof_index(v, 1);
      }
      if (cell->vertex_index(v) == b) pins[2] = cell->vertex_dof_index(v, b_component);
    }
  return pins;
}

void displacement_without_rigid_motion(const DoFHandler<2>& dof_handler,
                                       const Vector<double>& solution,
                                       const std::vector<int>& grid_to_mesh_vertex,
                                       std::vector<double>& ux, std::vector<double>& uy) {
  const Triangulation<2>& tria = dof_handler.get_triangulation();
  // Displacement per vertex, less the rigid motion that best fits the
  //    loaded (outer) boundary: translation = weighted mean, rotation =
  //    weighted mean of x' x u / |x'|^2 about the weighted centroid.
  std::vector<double> gx(tria.n_vertices()), gy(tria.n_vertices());
  for (const auto& cell : dof_handler.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices()) {
      gx[cell->vertex_index(v)] = solution(cell->vertex_dof_index(v, 0));
      gy[cell->vertex_index(v)] = solution(cell->vertex_dof_index(v, 1));
    }
  const auto& verts = tria.get_vertices();
  double w_sum = 0, cx = 0, cy = 0;
  std::vector<std::pair<unsigned int, double>> boundary;  // vertex, weight
  for (const auto& cell : tria.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (loaded(cell->face(f))) {
        const double half = 0.5 * cell->face(f)->measure();
        for (unsigned int k = 0; k < 2; ++k)
          boundary.emplace_back(cell->face(f)->vertex_index(k), half);
      }
  for (const auto& [v, w] : boundary) {
    w_sum += w;
    cx += w * verts[v][0];
    cy += w * verts[v][1];
  }
  double tx = 0, ty = 0, omega = 0;
  if (w_sum > 0) {
    cx /= w_sum;
    cy /= w_sum;
    double moment = 0, inertia = 0;
    for (const auto& [v, w] : boundary) {
      const double px = verts[v][0] - cx, py = verts[v][1] - cy;
      tx += w * gx[v];
      ty += w * gy[v];
      moment += w * (px * gy[v] - py * gx[v]);
      inertia += w * (px * px + py * py);
    }
    tx /= w_sum;
    ty /= w_sum;
    omega = inertia > 0 ? moment / inertia : 0;
  }
  for (unsigned int v = 0; v < verts.size(); ++v) {
    const int m = grid_to_mesh_vertex[v];
    ux[m] = gx[v] - (tx - omega * (verts[v][1] - cy));
    uy[m] = gy[v] - (ty + omega * (verts[v][0] - cx));
  }
}

// sigma0 = -(sH n n + sV m m), n the direction of sH, m normal to it; with
// gravity both grow linearly with depth below reference_y.
SymmetricTensor<2, 2> initial_stress(const InsituSpec& spec, const Point<2>& x) {
  const FarField& ff = spec.far_field;
  const double depth = spec.gravity.reference_y - x[1];
  const double gamma = spec.gravity.unit_weight;
  const double sV = ff.sV + gamma * depth;
  const double sH = ff.sH + ff.sH / ff.sV * gamma * depth;
  const double beta = ff.angle_deg * kPi / 180;
  const double c = std::cos(beta), s = std::sin(beta);
  SymmetricTensor<2, 2> sigma;
  sigma[0][0] = -(sH * c * c + sV * s * s);
  sigma[1][1] = -(sH * s * s + sV * c * c);
  sigma[0][1] = -(sH - sV) * s * c;
  return sigma;
}

double initial_szz(const InsituSpec& spec, const Point<2>& x) {
  const FarField& ff = spec.far_field;
  if (ff.sZ) {
    const double depth = spec.gravity.reference_y - x[1];
    return -(*ff.sZ) * (ff.sV + spec.gravity.unit_weight * depth) / ff.sV;
  }
  // Plane strain from rest in the host ground (the core's material where a
  // mesh has no rock zone, e.g. a specimen that is all core).
  const auto& ground = spec.materials.rock ? spec.materials.rock : spec.materials.core;
  return ground->nu * trace(initial_stress(spec, x));
}

void solve_direct(const SparseMatrix<double>& matrix, Vector<double>& x,
                  const Vector<double>& rhs) {
  SparseDirectUMFPACK direct;
  try {
    direct.initialize(matrix);
  } catch (const ExceptionBase& e) {
    throw InputError(
        "insitu: the stiffness matrix is singular (UMFPACK could not factorise it): check "
        "that no zone has a zero modulus and that alpha > 0 leaves a stiff core or none");
  }
  direct.vmult(x, rhs);
}

BaseMoments base_moments(const dealii::Triangulation<2>& triangulation, const std::string& who) {
  double length = 0, first = 0, second = 0;  // int 1, int x, int x^2 over the base
  for (const auto& cell : triangulation.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary() && cell->face(f)->user_index() == kBase) {
        const double x0 = cell->face(f)->vertex(0)[0], x1 = cell->face(f)->vertex(1)[0];
        const double l = std::abs(x1 - x0);
        length += l;
        first += l * 0.5 * (x0 + x1);
        second += l * (x0 * x0 + x0 * x1 + x1 * x1) / 3;
      }
  if (!(length > 0))
    throw InputError(who +
                     ": with gravity the box needs a horizontal bottom edge: it carries the weight "
                     "the excavation removes (set gravity.unit_weight = 0 for this mesh)");
  BaseMoments b;
  b.length = length;
  b.x = first / length;
  b.inertia = second - length * b.x * b.x;
  return b;
}

}  // namespace grid

std::vector<InsituField> solve_insitu(const mesh::Mesh& mesh, const InsituSpec& spec) {
  validate(mesh, spec);
  try {
    std::vector<InsituField> fields = InsituProblem(mesh, spec).run();
    malloc_trim(0);  // the grid, matrix and hierarchy, given back (see build_amg)
    return fields;
  } catch (const ExceptionBase& e) {
    // deal.II's checks that are always on (AssertThrow): report them once,
    // as the numerical failure they are.
    throw NumericalError(std::string("insitu: deal.II stopped: ") + e.what());
  }
}

}  // namespace rockfdem::insitu
