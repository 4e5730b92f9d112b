// run_crack_batch (crack_batch.hpp): the kernel of crack_batch_kernel.hpp
// for each instruction set, chosen by simd_isa.hpp.
#include "crack_batch.hpp"

namespace rockfdem::fdem::detail {
namespace {

#define ROCKFDEM_ISA_KERNEL "crack_batch_kernel.hpp"
#include "isa_regions.hpp"

#if defined(__x86_64__)
__attribute__((target("avx512f,avx512dq"))) void crack_avx512(CrackBatch& b, int n,
                                                              const CrackConstants& k) {
  avx512::crack_loop<V8>(b, n, k);
}
__attribute__((target("avx2"))) void crack_avx2(CrackBatch& b, int n, const CrackConstants& k) {
  avx2::crack_loop<V4>(b, n, k);
}
#endif

}  // namespace

void run_crack_batch(CrackBatch& b, int n, const CrackConstants& k, SimdIsa isa) {
  if (isa == SimdIsa::kBest) isa = resolved_simd_isa();
  switch (isa) {
#if defined(__x86_64__)
    case SimdIsa::kAvx512:
      crack_avx512(b, n, k);
      return;
    case SimdIsa::kAvx2:
      crack_avx2(b, n, k);
      return;
#endif
    default:
      baseline::crack_loop<V2>(b, n, k);
  }
}

}  // namespace rockfdem::fdem::detail
