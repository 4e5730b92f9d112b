// The narrow phase's arithmetic, a batch of roles at a time (private to
// fdem/).
//
// A role is one contactor triangle's three edges against one target
// triangle (contact_force.cpp explains the mathematics); a pair has two.
// The pair loop copies the pairs whose boxes overlap into a PairBatch, a
// structure of arrays with one lane per pair; run_roles computes both roles
// of every lane with selects where a scalar loop would branch (clipping,
// the breakpoints of the potential, the exact integrals, friction and
// damping), so that the lanes map onto the vector unit, and sums each
// pair's forces in the order a scalar loop over its roles and edges would.
//
// Same bits on every instruction set: the kernel is compiled once for
// AVX-512, AVX2 and the x86-64 baseline (SSE2) and chosen at run time, and
// its file is compiled without floating-point contraction, so each lane
// performs exactly the IEEE operations of the scalar formulas, in the same
// order, whichever width runs it (for finite potentials: docs/engine.md).
#pragma once

#include "simd_isa.hpp"

namespace rockfdem::fdem::detail {

/// Pairs per batch: the batch's arrays (about 25 kB) stay in the L1 cache.
/// The kernel runs whole registers of up to 8 lanes.
constexpr int kPairBatch = 32;
static_assert(kPairBatch % 8 == 0, "whole 8-lane registers");

/// The settings every pair of a step shares.
struct RoleParams {
  double p = 0, dt = 0, damping = 0;  ///< penalty, step, contact damping ratio
  bool friction = false;
};

/// One triangle of every lane's pair, as contact_force.cpp packs it.
/// [i][r]: component i (corner or edge; edge k runs from corner k to
/// k + 1) of lane r.
struct TriLanes {
  double x[3][kPairBatch], y[3][kPairBatch], vx[3][kPairBatch], vy[3][kPairBatch];
  double m[3][kPairBatch];                                          ///< corner masses (damping)
  double len[3][kPairBatch], ex[3][kPairBatch], ey[3][kPairBatch];  ///< length, unit tangent
  double gx[3][kPairBatch], gy[3][kPairBatch];  ///< gradients of the barycentric coordinates
  double h[kPairBatch];                         ///< smallest altitude
  double two_a[kPairBatch];                     ///< twice the area (> 0: may be a target)
};

/// One batch of pairs (A, B): role 0 is A's edges against B, role 1 B's
/// against A. Row j = 3 role + k of the per-edge arrays is edge k of role
/// `role`.
struct PairBatch {
  TriLanes tri[2];        ///< A, B
  double mu[kPairBatch];  ///< friction coefficient of the pair
  /// Friction springs: read, and written as the scalar loop would (set where
  /// an edge touches, reset where it does not, kept where the role is
  /// skipped because its target has no positive area).
  double spring[6][kPairBatch];
  /// Outputs: the pair's 12 corner forces (A's corners x, y, then B's),
  /// summed in the scalar loop's order (role 0's edges, then role 1's), the
  /// energy each edge dissipated (0 where it does not touch), and 1 where
  /// some edge touches, else 0.
  double force[12][kPairBatch];
  double loss_friction[6][kPairBatch], loss_damping[6][kPairBatch];
  double touching[kPairBatch];
};

/// Lanes 0 .. n - 1 of `b`: both roles of every pair, their forces,
/// springs and dissipation, on instruction set `isa` (must be available).
void run_roles(PairBatch& b, int n, const RoleParams& rp, SimdIsa isa = SimdIsa::kBest);

}  // namespace rockfdem::fdem::detail
