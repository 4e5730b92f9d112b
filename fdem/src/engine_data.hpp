// The engine's state as structure-of-arrays. Private to fdem/: the kernels
// (triangle_force, crack_elements, node_update) read and write these arrays
// directly; Engine::Impl (engine_impl.hpp) holds one behind the public Engine.
//
// Force slots: every triangle writes its three nodal forces into its own
// slots [3t, 3t+3), every crack element the forces on its nodes 0 and 1
// into [3 n_tri + 2c, 3 n_tri + 2c + 2); nodes 3 and 2 receive exactly
// their negatives (the element's forces balance), which the gather applies.
// Each node then gathers its incident slots in the order of the element
// corners (triangles, then crack elements' nodes 0-3; CSR built once). No
// two loop iterations write the same memory, so results do not depend on
// the thread count.
//
// Single precision: what the step computes (positions, velocities, forces,
// F0^-1) is double; constants of the model and the hand-off (masses,
// areas, damping coefficients, stiffness and strength factors, initial
// stresses, crack offsets) and the crack damage, a history maximum, are
// float. Their rounding (about 6e-8 of each value) lies far below what
// they are known to (a solver's tolerance, a lumped mass, a fitted
// constant) and saves about 80 B per triangle. Damage is rounded up as it
// is stored (round_up_to_float): the law never sees a stored history below
// the one it reached, so a point does not grow again by its rounding.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "contact.hpp"
#include "energy.hpp"
#include "node_list.hpp"
#include "rockfdem/fdem/crack_law.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/fdem/model_input.hpp"

namespace rockfdem::fdem::detail {

/// A node's slot entry (Nodes::slot_index): the slot, and the sign its
/// force enters the node with.
inline int entry_slot(int entry) { return entry >> 1; }

/// A load, not a branch: a node's entries mix both signs in no pattern a
/// branch predictor can follow.
inline double entry_sign(int entry) {
  static constexpr double kSign[2] = {1.0, -1.0};
  return kSign[entry & 1];
}

/// The least float at or above v (v finite, in float's range).
inline float round_up_to_float(double v) {
  const float f = static_cast<float>(v);
  return static_cast<double>(f) < v ? std::nextafter(f, INFINITY) : f;
}

/// A crack point's offsets (o0, s0) as stored for a point meant to see
/// opening o and slip s at openings (cur_o, cur_s): rounded so that it
/// sees no more tension (o) and no more slip (|s|) than meant. A point
/// pre-stressed to its strength sits just below its peak (pre_peak_
/// displacement); rounded to nearest, half of them would start past it,
/// damaged (measured: the jointed tunnel's wall block then creeps).
inline void store_offsets(double cur_o, double cur_s, double o, double s, float* out) {
  out[0] = round_up_to_float(cur_o - o);  // cur_o - out[0] <= o
  out[1] = s >= 0.0 ? round_up_to_float(cur_s - s) : -round_up_to_float(s - cur_s);
}

/// The entry of EngineData::broken_by_mode that a broken element of
/// failure mode `mode` counts in.
inline int broken_mode_entry(std::uint8_t mode) {
  if (mode == std::uint8_t(FailureMode::kModeI)) return 0;
  return mode == std::uint8_t(FailureMode::kModeII) ? 1 : 2;
}

/// Per-material constants the triangle kernel needs.
struct SolidConstants {
  double mu = 0, lambda = 0;  ///< Lame constants (lambda* in plane stress)
  double rho = 0;
  double cp = 0, cs = 0;     ///< P and S wave speeds (absorbing boundaries)
  bool plane_strain = true;  ///< sigma_zz follows from J (plane strain) or is 0 (plane stress)
};

/// Constant nodal forces (gravity + tractions [N/m]). With gravity every
/// node carries its weight and `force` holds 2 per node; without, only the
/// few nodes of loaded boundaries carry one: `node` lists them ascending
/// and `force` holds 2 per entry. Both empty without any load.
struct DeadLoads {
  bool dense = false;             ///< `force` is per node (gravity)
  std::vector<int> node;          ///< the loaded nodes, ascending (not dense)
  std::vector<double> force;      ///< interleaved x, y
  double none_x = 0, none_y = 0;  ///< the force of an unlisted node: 0 times gravity (its
                                  ///< zero's sign as a per-node array would hold it)
  /// Index of node i's force in `force` / 2, or -1 without one.
  long find(long i) const {
    if (dense) return force.empty() ? -1 : i;
    return index_in(node, i);
  }
};

struct Nodes {
  std::vector<double> pos, vel;    ///< interleaved x, y
  std::vector<double> vertex_pos;  ///< per mesh vertex, interleaved: the displacement origin
                                   ///< (nodes of one vertex share it: mesh_position())
  std::vector<float> mass;         ///< lumped; 0: no active triangle (frozen)
  DeadLoads fext;                  ///< gravity + tractions (dead loads)
  std::vector<int> bc_node;        ///< nodes with a boundary record, ascending; the
                                   ///< k-th one's record is bc_records[k]
  std::vector<int> vertex;         ///< mesh vertex of each node
  std::vector<int> slot_start;     ///< CSR over force slots, n + 1 entries
  std::vector<int> slot_index;     ///< 2 slot + 1 where the node takes the slot's negative
  std::size_t size() const { return mass.size(); }
  /// Node i's index into the boundary records, or -1 (a search: the node
  /// loop walks bc_node with a NodeListCursor).
  long bc(long i) const { return index_in(bc_node, i); }
  /// Coordinate `axis` of node i's mesh vertex.
  double mesh_position(std::size_t i, int axis) const { return vertex_pos[2 * vertex[i] + axis]; }
};

struct Triangles {
  std::vector<int> nodes;             ///< 3 per triangle
  std::vector<double> ref_inv;        ///< F0^-1 row-major, 4 per triangle
  std::vector<float> area0;           ///< reference area
  std::vector<float> eta;             ///< viscous damping coefficient [Pa s]
  std::vector<float> alpha;           ///< stiffness factor
  std::vector<float> sigma0;          ///< initial stress (sxx, syy, sxy); empty if none
  std::vector<float> viscous_stress;  ///< dt/2 A alpha eta D of the last step (3 per
                                      ///< triangle; empty without viscous damping): the energy
                                      ///< ledger books its work with the next velocities.
                                      ///< Single precision: only the ledger reads it
  std::vector<float> mass_scale;      ///< density factor >= 1 (mass_scaling.cpp); empty when off
  std::vector<std::uint16_t> material;
  std::vector<std::uint8_t> active;
  std::size_t size() const { return area0.size(); }
  double density_factor(std::size_t t) const { return mass_scale.empty() ? 1.0 : mass_scale[t]; }
};

struct Cracks {
  std::vector<int> nodes;     ///< 4 per element: 0,1 first face; 3 faces 0, 2 faces 1
  std::vector<float> damage;  ///< 3 per element (end 0, midpoint, end 1), rounded up
  std::vector<std::uint16_t> material;
  std::vector<std::uint8_t> state;   ///< CrackState
  std::vector<std::uint8_t> mode;    ///< FailureMode
  std::vector<std::uint8_t> active;  ///< both triangles active
  std::vector<std::int32_t> broken_step;
  /// Per kEnergyBlock elements: 1 when one of them broke in the last crack
  /// pass (contact_breaks looks there only).
  std::vector<std::uint8_t> broke_in_block;
  std::vector<float> offset;        ///< (o, s) taken as zero at end 0, midpoint, end 1
                                    ///< (6 per element); empty until an element is
                                    ///< re-joined or pre-stressed (crack_prestress.cpp)
  std::vector<float> strength;      ///< strength factor k (ft and c times k) per element;
                                    ///< empty while every factor is 1
                                    ///< (strength_heterogeneity.hpp)
  std::vector<int> joints;          ///< the elements with the joint law, ascending
  std::vector<double> joint_force;  ///< 4 per element of `joints`, in its order: the last
                                    ///< step's residual friction forces on nodes 0, 1
                                    ///< (joint_friction.hpp)
  std::size_t size() const { return material.size(); }
};

/// Kinematic and dashpot conditions of the few nodes that have any.
struct BoundaryRecord {
  Constraint x = Constraint::kFree, y = Constraint::kFree;
  double vx = 0, vy = 0;
  double cxx = 0, cxy = 0, cyy = 0;  ///< dashpot matrix [N s/m^2]: f = -C v
};

/// A tagged edge resolved to the triangle that owns it: corners ka -> kb run
/// counter-clockwise in that triangle.
struct EdgeRef {
  int tag = 0, tri = 0, ka = 0, kb = 0;
};

/// Constant nodal force from a traction or pressure (dead load).
struct NodalLoad {
  int node = 0;
  double fx = 0, fy = 0;
};

/// Nodes whose velocity a tag prescribes (reaction forces are summed over them).
struct TagNodes {
  int tag = 0;
  std::vector<int> nodes;
};

/// Kinetic damping's memory between steps (kinetic_damping.hpp).
struct KineticDampingState {
  double previous = 0;  ///< total kinetic energy after the last step
  bool rising = false;  ///< it rose in the last step
  long resets = 0;      ///< peaks at which the velocities were zeroed
};

struct EngineData {
  Nodes nodes;
  Triangles tris;
  Cracks cracks;
  std::vector<SolidConstants> solids;      ///< per material
  std::vector<CrackConstants> crack_laws;  ///< per material
  std::vector<Material> materials;
  std::vector<BoundaryRecord> bc_records;
  std::vector<EdgeRef> edges;
  std::vector<int> vertex_node_start, vertex_nodes;  ///< CSR mesh vertex -> engine nodes
  std::vector<NodalLoad> loads;
  std::vector<TagNodes> tag_nodes;
  bool masses_dirty = true;            ///< rebuild masses, fext, crack activity before stepping
  bool dead_loads = false;             ///< some fext is not zero (gravity or boundary loads)
  std::vector<double> slots;           ///< interleaved fx, fy per slot
  std::vector<double> block_partial;   ///< node loop: kNodeSums partial sums per node block
  std::vector<double> energy_partial;  ///< triangle and crack loops: one per kEnergyBlock
  double reversal[2] = {0, 0};         ///< sum m v_old.v_new, sum m v_old^2 (free nodes)
  double kinetic_after_step = 0;       ///< kinetic_energy() after the node loop (kinetic damping)
  double fastest_speed = 0;            ///< the node loop's largest node speed (contact's drift)
  DampingSettings damping;
  KineticDampingState kinetic_damping;
  MassScaling mass_scaling;
  double scaled_dt = 0;  ///< mass scaling's resolved target step without local damping;
                         ///< 0 until resolved
  double gravity[2] = {0, 0};
  bool contact_on = false;  ///< ContactSettings::enabled
  ContactData contact;
  EnergyLedger energy;  ///< accumulated energy terms (energy.hpp)
  double dt = 0;
  long step = 0;
  /// Broken crack elements by mode (I, II, mixed or unclassified), kept
  /// with the states by crack_forces and rejoin_crack, so that counting
  /// them (a trigger asks after every step) does not scan the elements.
  std::array<long, 3> broken_by_mode{};
  double time = 0;
  int threads = 0;
  /// crack_forces sends rock elements through the batch kernel; off, every
  /// element takes the scalar loop (the reference the tests compare with).
  bool crack_batch = true;
  std::size_t crack_slot0() const { return 3 * tris.size(); }
  /// Coordinate `axis` of node i at the last contact detection: the
  /// reference of the boxes, the separation test and the drift check.
  double detected_position(std::size_t i, int axis) const {
    return nodes.mesh_position(i, axis) + double(contact.detect_shift[2 * i + axis]);
  }
  /// Crack element e's triangle on `side` (0: its nodes 0, 1; 1: its nodes
  /// 3, 2), from the slots of the side's first node: the one triangle there
  /// that has the side's second node too. Not stored (8 B per element):
  /// asked for at stage changes and detections, never per step.
  int crack_triangle(std::size_t e, int side) const {
    const int a = cracks.nodes[4 * e + 3 * side], b = cracks.nodes[4 * e + 1 + side];
    const int slot0 = static_cast<int>(crack_slot0());
    for (int q = nodes.slot_start[a]; q < nodes.slot_start[a + 1]; ++q) {
      const int s = entry_slot(nodes.slot_index[q]);
      if (s >= slot0) break;  // a node's triangle slots come before its crack slots
      const int* tn = &tris.nodes[3 * (s / 3)];
      if (tn[0] == b || tn[1] == b || tn[2] == b) return s / 3;
    }
    return -1;  // unreachable: both of a side's nodes are corners of its triangle
  }
};

}  // namespace rockfdem::fdem::detail
