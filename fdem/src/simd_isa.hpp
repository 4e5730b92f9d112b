// Which vector instruction set the engine's kernels run on (private to
// fdem/). The contact narrow phase (contact_roles.hpp) and the crack
// elements (crack_batch.hpp) are each compiled for AVX-512, AVX2 and the
// baseline (SSE2 on x86-64), and give the same bits on all of them; only
// the speed differs. This picks one, once per process.
#pragma once

namespace rockfdem::fdem::detail {

/// Instruction sets a kernel may use; kBest is the widest this processor
/// has (or a narrower one that ROCKFDEM_ISA asks for). The others exist so
/// that tests can compare them bit by bit.
enum class SimdIsa { kBaseline, kAvx2, kAvx512, kBest };

/// Whether this processor can run `isa`.
bool simd_isa_available(SimdIsa isa);

/// The set kBest resolves to (never kBest).
SimdIsa resolved_simd_isa();

/// Name of the set kBest resolves to ("avx512", "avx2", "sse2"; "baseline"
/// on other processors, at their own 128-bit width).
const char* simd_isa_name();

/// Checks ROCKFDEM_ISA (unset, sse2, avx2 or avx512; else throws
/// InputError) and resolves kBest, once per process, outside any parallel
/// region (the Engine's constructor and the command line call it).
void check_simd_isa_request();

}  // namespace rockfdem::fdem::detail
