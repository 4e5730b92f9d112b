// The Mohr-Coulomb continuum as a deal.II program (step-42's Newton loop on
// the elastic stage's grid, without contact).
//
// ## The mathematics
//
// The rock starts at rest under sigma0 (tension positive, in equilibrium with
// the far-field traction t = sigma0 . n on the box). The opening (zone kCore,
// and kLining until the lining is installed) is out of the system from the
// start; its wall carries the fictitious support pressure of the
// convergence-confinement method, (1 - lambda) times the in-situ traction.
// With u measured from the in-situ state, equilibrium at release lambda is
//
//     R(u) = sum_cells int sigma(u) : eps(v) - F_box - (1 - lambda) W = 0,   (1)
//
// F_box = int_box sigma0 . n . v (plus the rock's weight int b . v with
// gravity), W = int_wall sigma0 . n . v. We form F_box as F0 - W_rock, with
// F0 = int_rock sigma0 : eps(v): at lambda = 0 the rock then sits exactly at
// sigma0, whatever the quadrature. With gravity the base of the box takes
// the weight the released wall no longer carries (below). In the rock sigma(u)
// is the Mohr-Coulomb stress update (mohr_coulomb.hpp; with a residual
// strength the softening one, mohr_coulomb_softening.hpp, whose gamma_p is
// state like the stress) from the last converged state; in an installed
// lining it is C_lining (eps - eps_install).
//
// Newton: K du = -R(u) with K the algorithmic tangent, not symmetric when
// psi != phi, so every step is solved by UMFPACK. lambda grows in steps of
// at most max_increment up to each reported value; a step that does not
// converge in max_newton iterations is halved.
//
// The lining: at lambda_install = 1 - install_alpha the ring's cells join,
// stress-free on the displacement they get (their new vertices take the
// displacement of the nearest wall vertex); from then on W is taken on the
// lining's inner face, the rock wall being inside the body.
//
// One quadrature point per cell (the centroid): P1 strain is constant per
// triangle, and the stress the return mapping gives is constant with it.
// Boundary conditions, rigid motion and its removal are the elastic stage's.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <unordered_set>
#include <vector>

#include "dealii_grid.hpp"
#include "mohr_coulomb_softening.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/insitu/plastic.hpp"

namespace rockfdem::insitu {

namespace {

using namespace dealii;

SymmetricTensor<2, 2> in_plane(const mc::Stress4& s) {
  SymmetricTensor<2, 2> t;
  t[0][0] = s[0];
  t[1][1] = s[1];
  t[0][1] = s[3];
  return t;
}

/// The 3x3 tangent d(s_xx, s_yy, s_xy)/d(e_xx, e_yy, e_xy) as D_ijkl: the
/// e_xy column acts through e_xy and e_yx, hence the halves.
SymmetricTensor<4, 2> as_tensor(const mc::Mat3& M) {
  SymmetricTensor<4, 2> D;
  const unsigned int ij[3][2] = {{0, 0}, {1, 1}, {0, 1}};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      D[ij[a][0]][ij[a][1]][ij[b][0]][ij[b][1]] = b == 2 ? 0.5 * M[a][b] : M[a][b];
  return D;
}

mc::Vec3 components(const SymmetricTensor<2, 2>& e) { return {e[0][0], e[1][1], e[0][1]}; }

class PlasticProblem {
 public:
  PlasticProblem(const mesh::Mesh& mesh, const InsituSpec& spec, const PlasticSpec& plastic);
  std::vector<PlasticField> run();

 private:
  void make_system();
  void install_lining();
  void assemble_loads();
  void assemble_base_loads();
  std::array<double, 3> resultant(const Vector<double>& f) const;
  void add_base_correction(double lambda);
  double assemble(double lambda);
  bool newton(double lambda, int& iterations);
  bool advance(double from, double to, PlasticField& field);
  void commit();
  void output(double lambda, PlasticField& field);

  const mesh::Mesh& mesh_;
  const InsituSpec& spec_;
  const PlasticSpec& plastic_;
  const mc::SofteningLaw rock_;
  const mc::Law lining_;
  const bool has_lining_;
  bool lining_installed_ = false;

  std::unordered_set<std::uint64_t> outer_edges_;
  grid::GridMap map_;
  Triangulation<2> triangulation_;
  const FESystem<2> fe_;
  const MappingFE<2> mapping_;
  const QGaussSimplex<2> quadrature_;
  const QGaussSimplex<1> face_quadrature_;
  std::unique_ptr<FEValues<2>> fe_values_;
  DoFHandler<2> dof_handler_;
  AffineConstraints<double> constraints_;
  std::vector<types::global_dof_index> pins_;
  SparsityPattern sparsity_pattern_;
  SparseMatrix<double> system_matrix_;
  Vector<double> solution_, step_start_, system_rhs_;
  int failed_steps_ = 0;      ///< failed Newton steps over the whole release (max_failed_steps)
  double reached_ = 0;        ///< the last lambda whose step converged
  Vector<double> box_load_;   ///< F0 - W_rock: the far-field traction (and the weight)
  Vector<double> wall_load_;  ///< W on the present wall
  double force_scale_ = 1;    ///< ||F0||
  // Gravity: the base tractions t_y = 1 and t_y = x - base_x_ that give the
  // weight released with the wall back to the base (see "Gravity" below),
  // and the resultants (F_x, F_y, M about the origin) of the two loads.
  Vector<double> base_uniform_, base_linear_;
  double base_length_ = 0, base_x_ = 0, base_inertia_ = 0;
  std::array<double, 3> box_resultant_{}, wall_resultant_{};

  // Per mesh triangle: the converged state and the present iterate.
  std::vector<mc::Stress4> sigma_n_, sigma_;
  std::vector<SymmetricTensor<2, 2>> eps_n_, eps_install_;
  std::vector<double> gamma_n_, gamma_;  ///< gamma_p, converged and iterate
  std::vector<std::uint8_t> yielded_, flowing_;
};

mc::SofteningLaw rock_law(const ElasticMaterial& rock, const PlasticSpec& p) {
  mc::Softening s;
  s.peak = mc::Material{rock.E, rock.nu, p.rock.cohesion, p.rock.friction_deg, p.rock.dilation_deg};
  s.residual = s.peak;
  if (p.residual) {
    s.residual.cohesion = p.residual->cohesion;
    s.residual.friction_deg = p.residual->friction_deg;
    s.gamma_res = p.residual->softening_strain;
  }
  return mc::SofteningLaw(s);
}

PlasticProblem::PlasticProblem(const mesh::Mesh& mesh, const InsituSpec& spec,
                               const PlasticSpec& plastic)
    : mesh_(mesh),
      spec_(spec),
      plastic_(plastic),
      rock_(rock_law(*spec.materials.rock, plastic)),
      lining_(mc::Material{spec.materials.lining ? spec.materials.lining->E : 1.0,
                           spec.materials.lining ? spec.materials.lining->nu : 0.0, 0, 30, 0}),
      has_lining_(spec.lining.active && spec.materials.lining &&
                  std::count(mesh.zone.begin(), mesh.zone.end(), mesh::kLining) > 0),
      outer_edges_(grid::outer_edges(mesh)),
      fe_(FE_SimplexP<2>(1), 2),
      mapping_(FE_SimplexP<2>(1)),
      quadrature_(1),
      face_quadrature_(3),
      sigma_n_(mesh.n_triangles()),
      sigma_(mesh.n_triangles()),
      eps_n_(mesh.n_triangles()),
      eps_install_(mesh.n_triangles()),
      gamma_n_(mesh.n_triangles(), 0.0),
      gamma_(mesh.n_triangles(), 0.0),
      yielded_(mesh.n_triangles(), 0),
      flowing_(mesh.n_triangles(), 0) {
  // The in-situ stress at each centroid: the state every rock cell starts from.
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Point<2> x((mesh.x[tri[0]] + mesh.x[tri[1]] + mesh.x[tri[2]]) / 3,
                     (mesh.y[tri[0]] + mesh.y[tri[1]] + mesh.y[tri[2]]) / 3);
    const SymmetricTensor<2, 2> s0 = grid::initial_stress(spec, x);
    sigma_n_[t] = {s0[0][0], s0[1][1], grid::initial_szz(spec, x), s0[0][1]};
  }
  sigma_ = sigma_n_;
}

std::vector<PlasticField> PlasticProblem::run() {
  make_system();
  std::vector<PlasticField> fields;
  const double install = has_lining_ ? 1 - spec_.lining.install_alpha : 2.0;
  double lambda = 0;
  for (const double target : plastic_.release) {
    PlasticField field;
    Timer timer;
    const auto keep = [&](const double at) {
      output(at, field);
      field.seconds = timer.wall_time();
      fields.push_back(std::move(field));
    };
    // A step failed under stop_at_failure: what was reached, and maybe where.
    const auto stopped = [&] {
      if (plastic_.output_at_failure && reached_ > lambda) keep(reached_);
      return std::move(fields);
    };
    if (!lining_installed_ && install < target) {
      if (install > lambda && !advance(lambda, install, field)) return stopped();
      lambda = std::max(lambda, install);
      install_lining();
    }
    if (!advance(lambda, target, field)) return stopped();
    lambda = target;
    keep(lambda);
  }
  return fields;
}

// ---------------------------------------------------------------------------
// The system on the present grid: rock, plus the lining once installed.
// ---------------------------------------------------------------------------

void PlasticProblem::make_system() {
  std::vector<std::uint8_t> removed(mesh_.n_triangles());
  for (std::size_t t = 0; t < mesh_.n_triangles(); ++t)
    removed[t] =
        !(mesh_.zone[t] == mesh::kRock || (lining_installed_ && mesh_.zone[t] == mesh::kLining));
  fe_values_.reset();
  system_matrix_.clear();
  dof_handler_.clear();
  map_ = grid::build_triangulation(mesh_, removed, outer_edges_, triangulation_);
  dof_handler_.reinit(triangulation_);
  dof_handler_.distribute_dofs(fe_);
  pins_ = grid::rigid_motion_pins(dof_handler_);
  constraints_.clear();
  for (const auto dof : pins_) constraints_.add_line(dof);
  constraints_.close();
  DynamicSparsityPattern dsp(dof_handler_.n_dofs(), dof_handler_.n_dofs());
  DoFTools::make_sparsity_pattern(dof_handler_, dsp, constraints_, false);
  sparsity_pattern_.copy_from(dsp);
  system_matrix_.reinit(sparsity_pattern_);
  solution_.reinit(dof_handler_.n_dofs());
  system_rhs_.reinit(dof_handler_.n_dofs());
  fe_values_ = std::make_unique<FEValues<2>>(
      mapping_, fe_, quadrature_,
      update_values | update_gradients | update_quadrature_points | update_JxW_values);
  assemble_loads();
}

// The ring joins: new grid and dofs; the displacement carried over by mesh
// vertex, a new (inner) vertex taking that of the nearest old one.
void PlasticProblem::install_lining() {
  std::vector<double> ux(mesh_.n_vertices(), 0), uy(mesh_.n_vertices(), 0);
  std::vector<std::uint8_t> known(mesh_.n_vertices(), 0);
  std::vector<int> old_vertices;
  for (const auto& cell : dof_handler_.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices()) {
      const int m = map_.grid_to_mesh_vertex[cell->vertex_index(v)];
      if (known[m]) continue;
      known[m] = 1;
      ux[m] = solution_(cell->vertex_dof_index(v, 0));
      uy[m] = solution_(cell->vertex_dof_index(v, 1));
      old_vertices.push_back(m);
    }
  lining_installed_ = true;
  make_system();
  for (const auto& cell : dof_handler_.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices()) {
      int m = map_.grid_to_mesh_vertex[cell->vertex_index(v)];
      if (!known[m]) {
        double best = std::numeric_limits<double>::max();
        int nearest = m;
        for (const int o : old_vertices) {
          const double d = std::hypot(mesh_.x[o] - mesh_.x[m], mesh_.y[o] - mesh_.y[m]);
          if (d < best) best = d, nearest = o;
        }
        m = nearest;
      }
      solution_(cell->vertex_dof_index(v, 0)) = ux[m];
      solution_(cell->vertex_dof_index(v, 1)) = uy[m];
    }
  // Stress-free on that displacement.
  const FEValuesExtractors::Vector displacement(0);
  std::vector<SymmetricTensor<2, 2>> eps_q(1);
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    const int t = map_.cell_to_triangle[cell->active_cell_index()];
    if (mesh_.zone[t] != mesh::kLining) continue;
    fe_values_->reinit(cell);
    (*fe_values_)[displacement].get_function_symmetric_gradients(solution_, eps_q);
    eps_install_[t] = eps_n_[t] = eps_q[0];
    sigma_n_[t] = sigma_[t] = mc::Stress4{};
  }
}

// F0 - W_rock and W on the present grid (see (1)). W_rock is the in-situ
// traction on the faces of rock cells that face the opening or the lining.
void PlasticProblem::assemble_loads() {
  FEFaceValues<2> face_values(
      mapping_, fe_, face_quadrature_,
      update_values | update_quadrature_points | update_normal_vectors | update_JxW_values);
  const FEValuesExtractors::Vector displacement(0);
  const unsigned int n = fe_.n_dofs_per_cell();
  Vector<double> cell_box(n), cell_wall(n);
  std::vector<types::global_dof_index> dofs(n);
  Vector<double> f0(dof_handler_.n_dofs());
  box_load_.reinit(dof_handler_.n_dofs());
  wall_load_.reinit(dof_handler_.n_dofs());
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    const bool rock = mesh_.zone[map_.cell_to_triangle[cell->active_cell_index()]] == mesh::kRock;
    cell_box = 0;
    cell_wall = 0;
    fe_values_->reinit(cell);
    const SymmetricTensor<2, 2> s0 = grid::initial_stress(spec_, fe_values_->quadrature_point(0));
    if (rock)
      for (const unsigned int i : fe_values_->dof_indices())
        cell_box(i) +=
            ((*fe_values_)[displacement].symmetric_gradient(i, 0) * s0) * fe_values_->JxW(0);
    for (const unsigned int f : cell->face_indices()) {
      const auto face = cell->face(f);
      const bool opening = face->at_boundary() && face->user_index() == grid::kFree;
      const bool rock_wall =
          rock &&
          (opening || (!face->at_boundary() &&
                       mesh_.zone[map_.cell_to_triangle[cell->neighbor(f)->active_cell_index()]] !=
                           mesh::kRock));
      if (!opening && !rock_wall) continue;
      face_values.reinit(cell, f);
      for (const unsigned int q : face_values.quadrature_point_indices()) {
        const Tensor<1, 2> t = grid::initial_stress(spec_, face_values.quadrature_point(q)) *
                               face_values.normal_vector(q);
        for (const unsigned int i : face_values.dof_indices()) {
          const double w = (face_values[displacement].value(i, q) * t) * face_values.JxW(q);
          if (rock_wall) cell_box(i) -= w;
          if (opening) cell_wall(i) += w;
        }
      }
    }
    cell->get_dof_indices(dofs);
    box_load_.add(dofs, cell_box);
    wall_load_.add(dofs, cell_wall);
    if (rock)
      for (const unsigned int i : fe_values_->dof_indices())
        f0(dofs[i]) +=
            ((*fe_values_)[displacement].symmetric_gradient(i, 0) * s0) * fe_values_->JxW(0);
  }
  force_scale_ = std::max(f0.l2_norm(), 1e-300);
  if (spec_.gravity.unit_weight != 0) assemble_base_loads();
}

// ---------------------------------------------------------------------------
// Gravity. The released wall traction W has the weight of what was excavated
// as its resultant: releasing it unbalances the loads, and the three pins
// would carry the difference as point forces. As in the elastic stage the
// base of the box takes it instead: t_y = q0 + q1 (x - x_base) on the bottom
// edge, q0 and q1 such that force and moment of all loads vanish.
// ---------------------------------------------------------------------------

void PlasticProblem::assemble_base_loads() {
  FEFaceValues<2> face_values(mapping_, fe_, face_quadrature_,
                              update_values | update_quadrature_points | update_JxW_values);
  const FEValuesExtractors::Vector displacement(0);
  const grid::BaseMoments base = grid::base_moments(triangulation_, "insitu mohr_coulomb");
  base_length_ = base.length;
  base_x_ = base.x;
  base_inertia_ = base.inertia;
  base_uniform_.reinit(dof_handler_.n_dofs());
  base_linear_.reinit(dof_handler_.n_dofs());
  std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
  for (const auto& cell : dof_handler_.active_cell_iterators())
    for (const unsigned int f : cell->face_indices()) {
      if (!cell->face(f)->at_boundary() || cell->face(f)->user_index() != grid::kBase) continue;
      face_values.reinit(cell, f);
      cell->get_dof_indices(dofs);
      for (const unsigned int q : face_values.quadrature_point_indices())
        for (const unsigned int i : face_values.dof_indices()) {
          const double vy = face_values[displacement].value(i, q)[1] * face_values.JxW(q);
          base_uniform_(dofs[i]) += vy;
          base_linear_(dofs[i]) += vy * (face_values.quadrature_point(q)[0] - base_x_);
        }
    }
  box_resultant_ = resultant(box_load_);
  wall_resultant_ = resultant(wall_load_);
}

// Force and moment about the origin of nodal forces f.
std::array<double, 3> PlasticProblem::resultant(const Vector<double>& f) const {
  std::array<double, 3> r{};
  std::vector<std::uint8_t> seen(dof_handler_.n_dofs(), 0);
  for (const auto& cell : dof_handler_.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices()) {
      const auto dx = cell->vertex_dof_index(v, 0), dy = cell->vertex_dof_index(v, 1);
      if (seen[dx]) continue;
      seen[dx] = 1;
      r[0] += f(dx);
      r[1] += f(dy);
      r[2] += cell->vertex(v)[0] * f(dy) - cell->vertex(v)[1] * f(dx);
    }
  return r;
}

void PlasticProblem::add_base_correction(const double lambda) {
  if (spec_.gravity.unit_weight == 0) return;
  const double Fy = box_resultant_[1] + (1 - lambda) * wall_resultant_[1];
  const double M = box_resultant_[2] + (1 - lambda) * wall_resultant_[2];
  // q0 base_length_ = -Fy;  q0 base_length_ base_x_ + q1 base_inertia_ = -M.
  const double q0 = -Fy / base_length_;
  const double q1 = base_inertia_ > 0 ? (-M - q0 * base_length_ * base_x_) / base_inertia_ : 0;
  system_rhs_.add(q0, base_uniform_, q1, base_linear_);
}

// ---------------------------------------------------------------------------
// Newton.
// ---------------------------------------------------------------------------

// The tangent into system_matrix_ and -R(u) into system_rhs_ (constrained
// rows zeroed); the stresses of this iterate into sigma_. Returns ||R|| over
// the free dofs / ||F0||.
double PlasticProblem::assemble(const double lambda) {
  system_matrix_ = 0;
  system_rhs_ = 0;
  const FEValuesExtractors::Vector displacement(0);
  const unsigned int n = fe_.n_dofs_per_cell();
  FullMatrix<double> cell_matrix(n, n);
  Vector<double> cell_rhs(n);
  std::vector<types::global_dof_index> dofs(n);
  std::vector<SymmetricTensor<2, 2>> eps_q(1), eps_phi(n);
  const SymmetricTensor<4, 2> C_lining = as_tensor(mc::elastic_tangent(lining_));
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    fe_values_->reinit(cell);
    (*fe_values_)[displacement].get_function_symmetric_gradients(solution_, eps_q);
    const int t = map_.cell_to_triangle[cell->active_cell_index()];
    SymmetricTensor<4, 2> D;
    if (mesh_.zone[t] == mesh::kRock) {
      const mc::Result r =
          mc::update(rock_, sigma_n_[t], gamma_n_[t], components(eps_q[0] - eps_n_[t]), gamma_[t]);
      sigma_[t] = r.stress;
      flowing_[t] = r.kind != mc::Return::kElastic;
      D = as_tensor(r.tangent);
    } else {
      const SymmetricTensor<2, 2> s = C_lining * (eps_q[0] - eps_install_[t]);
      sigma_[t] = {s[0][0], s[1][1], lining_.lambda * trace(eps_q[0] - eps_install_[t]), s[0][1]};
      D = C_lining;
    }
    const SymmetricTensor<2, 2> sigma = in_plane(sigma_[t]);
    const double JxW = fe_values_->JxW(0);
    for (const unsigned int i : fe_values_->dof_indices())
      eps_phi[i] = (*fe_values_)[displacement].symmetric_gradient(i, 0);
    for (const unsigned int i : fe_values_->dof_indices()) {
      for (const unsigned int j : fe_values_->dof_indices())
        cell_matrix(i, j) = (eps_phi[i] * (D * eps_phi[j])) * JxW;
      cell_rhs(i) = -(eps_phi[i] * sigma) * JxW;
    }
    cell->get_dof_indices(dofs);
    constraints_.distribute_local_to_global(cell_matrix, cell_rhs, dofs, system_matrix_,
                                            system_rhs_);
  }
  system_rhs_.add(1.0, box_load_, 1 - lambda, wall_load_);
  add_base_correction(lambda);
  for (const auto dof : pins_) system_rhs_(dof) = 0;
  return system_rhs_.l2_norm() / force_scale_;
}

// A tangent with plastic flow in it can be singular: with softening at an
// iterate far from the answer (seen with gamma_res = 1e-2 at the 5th iterate
// of a 0.05 step), without it where the flowing cells form a mechanism
// (ground at its limit load). That step failed, and is halved like one that
// does not converge, so the release ends in the collapse verdict. A singular
// elastic tangent (nothing flowing) is the input's fault: the error stands.
bool PlasticProblem::newton(const double lambda, int& iterations) {
  Vector<double> du(dof_handler_.n_dofs());
  for (int it = 0; it <= plastic_.max_newton; ++it) {
    const double r = assemble(lambda);
    if (!std::isfinite(r)) return false;
    if (r <= plastic_.tolerance) return true;
    if (it == plastic_.max_newton) break;
    try {
      grid::solve_direct(system_matrix_, du, system_rhs_);
    } catch (const InputError&) {  // solve_direct's "singular"
      if (!rock_.softens() && std::count(flowing_.begin(), flowing_.end(), 1) == 0) throw;
      return false;
    }
    constraints_.distribute(du);
    solution_ += du;
    ++iterations;
  }
  return false;
}

// lambda from `from` to `to` in steps of at most max_increment, each halved
// while Newton fails (and doubled again after each success). False: a step
// failed max_halvings times under stop_at_failure (else that throws).
bool PlasticProblem::advance(const double from, const double to, PlasticField& field) {
  double lambda = from;
  int halvings = 0;
  double step = plastic_.max_increment;
  while (lambda < to - 1e-14) {
    const double next = std::min(to, lambda + step);
    step_start_ = solution_;
    if (newton(next, field.newton_iterations)) {
      commit();
      lambda = reached_ = next;
      ++field.steps;
      halvings = 0;
      step = std::min(plastic_.max_increment, 2 * step);
      continue;
    }
    solution_ = step_start_;
    ++failed_steps_;
    if (plastic_.max_failed_steps > 0 && failed_steps_ > plastic_.max_failed_steps) {
      if (plastic_.stop_at_failure) return false;
      throw NumericalError("insitu mohr_coulomb: the release failed " +
                           std::to_string(failed_steps_) +
                           " steps on the way to lambda = " + std::to_string(next) +
                           " (the ground creeps at the limit of collapse: no equilibrium "
                           "within the work allowed)");
    }
    if (++halvings > plastic_.max_halvings && plastic_.stop_at_failure) return false;
    if (halvings > plastic_.max_halvings)
      throw NumericalError(
          "insitu mohr_coulomb: the release step to lambda = " + std::to_string(next) +
          " did not converge after " + std::to_string(plastic_.max_halvings) +
          " halvings (the ground may collapse: check cohesion and friction)");
    step *= 0.5;
  }
  return true;
}

void PlasticProblem::commit() {
  const FEValuesExtractors::Vector displacement(0);
  std::vector<SymmetricTensor<2, 2>> eps_q(1);
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    const int t = map_.cell_to_triangle[cell->active_cell_index()];
    fe_values_->reinit(cell);
    (*fe_values_)[displacement].get_function_symmetric_gradients(solution_, eps_q);
    eps_n_[t] = eps_q[0];
    sigma_n_[t] = sigma_[t];
    gamma_n_[t] = gamma_[t];
    yielded_[t] = yielded_[t] || flowing_[t];
  }
}

void PlasticProblem::output(const double lambda, PlasticField& field) {
  field.lambda = lambda;
  field.lining_installed = lining_installed_;
  field.stress.assign(mesh_.n_triangles(), Stress{});
  field.active.assign(mesh_.n_triangles(), 0);
  field.yielded = yielded_;
  field.plastic_shear = gamma_n_;
  if (rock_.softens())
    field.n_residual =
        static_cast<std::size_t>(std::count_if(gamma_n_.begin(), gamma_n_.end(), [&](double g) {
          return g > 0 && g >= rock_.gamma_res();
        }));
  field.ux.assign(mesh_.n_vertices(), 0.0);
  field.uy.assign(mesh_.n_vertices(), 0.0);
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    const int t = map_.cell_to_triangle[cell->active_cell_index()];
    field.active[t] = 1;
    field.stress[t] = Stress{sigma_n_[t][0], sigma_n_[t][1], sigma_n_[t][3], sigma_n_[t][2]};
  }
  field.n_yielded = static_cast<std::size_t>(std::count(yielded_.begin(), yielded_.end(), 1));
  field.unbalanced_ratio = assemble(lambda);
  grid::displacement_without_rigid_motion(dof_handler_, solution_, map_.grid_to_mesh_vertex,
                                          field.ux, field.uy);
}

}  // namespace

std::vector<PlasticField> solve_mohr_coulomb(const mesh::Mesh& mesh, const InsituSpec& spec,
                                             const PlasticSpec& plastic) {
  validate(mesh, spec);
  validate(plastic);
  if (spec.loading != BoundaryLoading::kFarField)
    throw InputError("insitu mohr_coulomb: the plastic continuum needs far-field box loading");
  if (!spec.materials.rock)
    throw InputError("insitu mohr_coulomb: materials.rock (young, poisson) is required");
  try {
    PlasticProblem problem(mesh, spec, plastic);
    return problem.run();
  } catch (const ExceptionBase& e) {
    throw NumericalError(std::string("insitu mohr_coulomb: deal.II stopped: ") + e.what());
  }
}

}  // namespace rockfdem::insitu
