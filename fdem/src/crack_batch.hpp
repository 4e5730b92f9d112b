// The crack loop's common case, a batch of elements at a time (private to
// fdem/).
//
// In most steps most crack elements are rock elements whose damage does
// not grow: intact ones below their peaks, and softened ones whose
// excursion stays within their history. crack_forces copies the elements
// that are not broken (one material per batch, of a law with kBatched)
// into a CrackBatch; run_crack_batch evaluates their geometry, law and
// forces lane by lane without a branch and flags the lanes where some
// point's damage would grow. Those, and every other element (steel, another
// material), take the scalar path in element order, so the released
// energy, histories and state changes are those of a scalar loop.
// Same bits: one lane performs the scalar formulas' IEEE operations in
// their order (no contraction), as in contact_roles.hpp.
#pragma once

#include "rockfdem/fdem/crack_law.hpp"
#include "simd_isa.hpp"

namespace rockfdem::fdem::detail {

constexpr int kCrackBatch = 32;
static_assert(kCrackBatch % 8 == 0, "whole 8-lane registers");

/// Inputs: the four nodes' positions, the per-point offsets (o, s) (zero
/// when the model has none), damage histories and, in a heterogeneous
/// model, the strength factors (scaled_strength_terms). Outputs: the eight slot
/// values (node 0 x, y, node 1, node 2, node 3) and 1 where some point's
/// damage would grow (the lane's outputs are then meaningless and the
/// scalar path redoes it).
struct CrackBatch {
  double x[4][kCrackBatch], y[4][kCrackBatch];
  double off_o[3][kCrackBatch], off_s[3][kCrackBatch];
  double damage[3][kCrackBatch];
  double strength[kCrackBatch];  ///< read only when `scaled`
  double out[8][kCrackBatch];
  double grows[kCrackBatch];
};

/// Lanes 0 .. n - 1 of `b`, all of material constants `k` (any law), none
/// broken; `scaled`: each lane's strengths are its factor times k's.
void run_crack_batch(CrackBatch& b, int n, const CrackConstants& k, bool scaled,
                     SimdIsa isa = SimdIsa::kBest);

}  // namespace rockfdem::fdem::detail
