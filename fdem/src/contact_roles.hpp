// The narrow phase's arithmetic, a batch of roles at a time (private to
// fdem/).
//
// A role is one contactor triangle's three edges against one target
// triangle (contact_force.cpp explains the mathematics). The pair loop
// copies the roles of the pairs whose boxes overlap into a RoleBatch, a
// structure of arrays with one lane per role; run_roles computes every
// lane's three edges without a data-dependent branch (clipping, the
// breakpoints of the potential, the exact integrals, friction and damping
// as selects), so the compiler maps the lanes onto the vector unit; the
// pair loop then adds each edge's contributions to the pair's buffer in
// the same order as a scalar loop would.
//
// Same bits on every instruction set: the kernel is compiled once for
// AVX-512, AVX2 and the x86-64 baseline (SSE2) and chosen at run time, and
// its file is compiled without floating-point contraction, so each lane
// performs exactly the IEEE operations of the scalar formulas, in the same
// order, whichever width runs it.
#pragma once

namespace rockfdem::fdem::detail {

/// Roles per batch: the batch's arrays (about 23 kB) stay in the L1 cache.
constexpr int kRoleBatch = 32;

/// The settings every role of a step shares.
struct RoleParams {
  double p = 0, dt = 0, damping = 0;  ///< penalty, step, contact damping ratio
  bool friction = false;
};

/// One batch of roles: inputs (contactor C, target T), then outputs per
/// contactor edge k (corners k -> k + 1). [i][r]: component i of lane r.
struct RoleBatch {
  // Contactor corners and edges.
  double cx[3][kRoleBatch], cy[3][kRoleBatch], cvx[3][kRoleBatch], cvy[3][kRoleBatch];
  double cm[3][kRoleBatch];                                         ///< corner masses (damping)
  double len[3][kRoleBatch], ex[3][kRoleBatch], ey[3][kRoleBatch];  ///< length, unit tangent
  // Target corners, gradients of its barycentric coordinates, smallest altitude.
  double tx[3][kRoleBatch], ty[3][kRoleBatch], tvx[3][kRoleBatch], tvy[3][kRoleBatch];
  double gx[3][kRoleBatch], gy[3][kRoleBatch], h[kRoleBatch];
  double mu[kRoleBatch];  ///< friction coefficient of the pair
  /// Friction spring per edge: read, and written where the edge touches.
  double spring[3][kRoleBatch];
  // Outputs per edge k. hit: 1 where the edge overlaps the target (then the
  // rest is meaningful), else 0.
  double hit[3][kRoleBatch];
  double fc[3][4][kRoleBatch];  ///< contactor corners k, k + 1: x, y
  double ft[3][6][kRoleBatch];  ///< target corners 0, 1, 2: x, y
  double loss_friction[3][kRoleBatch], loss_damping[3][kRoleBatch];
};

/// Lanes 0 .. n - 1 of `b`: every edge's overlap, forces, spring and
/// dissipation. Targets must have a positive area (callers skip the others).
void run_roles(RoleBatch& b, int n, const RoleParams& rp);

/// Instruction sets run_roles may use; kBest is the widest this processor
/// has. The others exist so that tests can compare them bit by bit.
enum class RoleIsa { kBaseline, kAvx2, kAvx512, kBest };

/// Whether this processor can run `isa`.
bool role_isa_available(RoleIsa isa);

/// run_roles on the given instruction set (must be available).
void run_roles(RoleBatch& b, int n, const RoleParams& rp, RoleIsa isa);

/// Name of the instruction set kBest resolves to ("avx512", "avx2", "sse2").
const char* role_isa_name();

}  // namespace rockfdem::fdem::detail
