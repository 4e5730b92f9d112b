// Instantiates a vector kernel once per instruction set: the kernel header
// named by ROCKFDEM_ISA_KERNEL goes into namespace `baseline` (the
// compiler's default set: SSE2 on x86-64, 128-bit lanes elsewhere) and, on
// x86-64, into `avx2` and `avx512` inside regions compiled for those sets
// (GCC: target pragmas; Clang: a target attribute applied to every
// function). GCC lowers vector operations per function, by that function's
// own target, so the helpers must be compiled inside the region too, not
// only the loop that inlines them. (The crack laws' templates are the
// exception that proves the rule: written outside, always inlined, with
// comparisons only as selects' conditions; crack_law_parts.hpp says why.) No include guard: one
// inclusion per translation unit, inside that unit's namespace (contact_roles.cpp,
// crack_batch.cpp).

/// W doubles in one register (GCC vector extension).
typedef double V2 __attribute__((vector_size(16)));
typedef double V4 __attribute__((vector_size(32)));
typedef double V8 __attribute__((vector_size(64)));

namespace baseline {
#include ROCKFDEM_ISA_KERNEL
}  // namespace baseline

#if defined(__x86_64__)
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif
namespace avx2 {
#include ROCKFDEM_ISA_KERNEL
}  // namespace avx2
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx512f,avx512dq"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx512f,avx512dq")
#endif
namespace avx512 {
#include ROCKFDEM_ISA_KERNEL
}  // namespace avx512
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
#endif
