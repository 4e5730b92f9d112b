// Which crack elements of an engine lie on the mesh's joint traces, and how
// they stand: the joint material is given to them, outputs count them apart
// from the intact rock's cracks and flag them in the VTK files.
#pragma once

#include <cstdint>
#include <vector>

#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::coupling {

/// Per crack element: the index + 1 of the joint trace it lies on, 0 off
/// the joints (its first face's mesh vertices are a Mesh::joint_edges pair).
std::vector<std::int32_t> joint_crack_traces(const fdem::Engine& e, const mesh::Mesh& m);

/// The joint elements' state: with the joint law they never break, so
/// their damage tells how far each has gone.
struct JointCounts {
  long elements = 0;  ///< crack elements on joints
  long active = 0;    ///< of them, between two active triangles
  long yielding = 0;  ///< past the peak, softening towards the residual (0 < damage < 1)
  long residual = 0;  ///< cohesion and tension lost: sliding on residual friction (damage 1)
};

/// The opening of crack element c normal to its first face [m]: the mean
/// over its two node pairs (0 facing 3, 1 facing 2) of the second face's
/// node's distance from the first's along the first face's normal pointing
/// away from the first face's triangle; negative: the faces overlap.
double crack_normal_opening(const fdem::Engine& e, std::size_t c);

/// How a joint element stands in the pictures.
enum class JointState {
  kIntact,   ///< damage 0: below its peak strength
  kSliding,  ///< damage > 0: past the peak, softening or sliding at the residual friction
  kOpened,   ///< faces apart by more than the pictures' threshold
};

/// kOpened when crack_normal_opening exceeds `opened` [m], else kSliding
/// with damage > 0, else kIntact.
JointState joint_state(const fdem::Engine& e, std::size_t c, double opened);

/// Counts over the flags of joint_crack_traces (inactive elements count
/// only in `elements`).
JointCounts count_joint_cracks(const fdem::Engine& e, const std::vector<std::int32_t>& traces);

}  // namespace rockfdem::coupling
