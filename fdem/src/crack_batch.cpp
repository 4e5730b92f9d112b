// run_crack_batch (crack_batch.hpp): the kernel of crack_batch_kernel.hpp
// for each instruction set, chosen by simd_isa.hpp.
#include "crack_batch.hpp"

namespace rockfdem::fdem::detail {
namespace {

#define ROCKFDEM_ISA_KERNEL "crack_batch_kernel.hpp"
#include "isa_regions.hpp"

#if defined(__x86_64__)
__attribute__((target("avx512f,avx512dq"))) void crack_avx512(CrackBatch& b, int n,
                                                              const CrackConstants& k,
                                                              bool scaled) {
  if (scaled) {
    avx512::crack_loop<V8, true>(b, n, k);
  } else {
    avx512::crack_loop<V8, false>(b, n, k);
  }
}
__attribute__((target("avx2"))) void crack_avx2(CrackBatch& b, int n, const CrackConstants& k,
                                                bool scaled) {
  if (scaled) {
    avx2::crack_loop<V4, true>(b, n, k);
  } else {
    avx2::crack_loop<V4, false>(b, n, k);
  }
}
#endif

}  // namespace

void run_crack_batch(CrackBatch& b, int n, const CrackConstants& k, bool scaled, SimdIsa isa) {
  if (isa == SimdIsa::kBest) isa = resolved_simd_isa();
  switch (isa) {
#if defined(__x86_64__)
    case SimdIsa::kAvx512:
      crack_avx512(b, n, k, scaled);
      return;
    case SimdIsa::kAvx2:
      crack_avx2(b, n, k, scaled);
      return;
#endif
    default:
      if (scaled) {
        baseline::crack_loop<V2, true>(b, n, k);
      } else {
        baseline::crack_loop<V2, false>(b, n, k);
      }
  }
}

}  // namespace rockfdem::fdem::detail
