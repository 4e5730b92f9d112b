// run_crack_batch (crack_batch.hpp): the kernel of crack_batch_kernel.hpp
// for each instruction set, chosen as the contact kernel's is.
#include "crack_batch.hpp"

#define ROLE_INLINE inline __attribute__((always_inline))

namespace rockfdem::fdem::detail {
namespace {

typedef double V2 __attribute__((vector_size(16)));
typedef double V4 __attribute__((vector_size(32)));
typedef double V8 __attribute__((vector_size(64)));

namespace baseline {
#include "crack_batch_kernel.hpp"
}  // namespace baseline

#if defined(__x86_64__)
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif
namespace avx2 {
#include "crack_batch_kernel.hpp"
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
#include "crack_batch_kernel.hpp"
}  // namespace avx512
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

__attribute__((target("avx512f,avx512dq"))) void crack_avx512(CrackBatch& b, int n,
                                                              const CrackConstants& k) {
  avx512::crack_loop<V8>(b, n, k);
}
__attribute__((target("avx2"))) void crack_avx2(CrackBatch& b, int n, const CrackConstants& k) {
  avx2::crack_loop<V4>(b, n, k);
}
#endif

}  // namespace

void run_crack_batch(CrackBatch& b, int n, const CrackConstants& k, RoleIsa isa) {
  if (isa == RoleIsa::kBest) isa = resolved_role_isa();
  switch (isa) {
#if defined(__x86_64__)
    case RoleIsa::kAvx512:
      crack_avx512(b, n, k);
      return;
    case RoleIsa::kAvx2:
      crack_avx2(b, n, k);
      return;
#endif
    default:
      baseline::crack_loop<V2>(b, n, k);
  }
}

}  // namespace rockfdem::fdem::detail
