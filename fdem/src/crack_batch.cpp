// run_crack_batch (crack_batch.hpp): the kernel of crack_batch_kernel.hpp
// for each crack law and instruction set, the law picked by with_crack_law
// (crack_law.hpp), the set by simd_isa.hpp.
#include "crack_batch.hpp"

namespace rockfdem::fdem::detail {
namespace {

#define ROCKFDEM_ISA_KERNEL "crack_batch_kernel.hpp"
#include "isa_regions.hpp"

#if defined(__x86_64__)
template <class Law>
__attribute__((target("avx512f,avx512dq"))) void crack_avx512(CrackBatch& b, int n,
                                                              const CrackConstants& k,
                                                              bool scaled) {
  if (scaled) {
    avx512::crack_loop<V8, Law, true>(b, n, k);
  } else {
    avx512::crack_loop<V8, Law, false>(b, n, k);
  }
}
template <class Law>
__attribute__((target("avx2"))) void crack_avx2(CrackBatch& b, int n, const CrackConstants& k,
                                                bool scaled) {
  if (scaled) {
    avx2::crack_loop<V4, Law, true>(b, n, k);
  } else {
    avx2::crack_loop<V4, Law, false>(b, n, k);
  }
}
#endif

template <class Law>
void crack_isa(CrackBatch& b, int n, const CrackConstants& k, bool scaled, SimdIsa isa) {
  switch (isa) {
#if defined(__x86_64__)
    case SimdIsa::kAvx512:
      crack_avx512<Law>(b, n, k, scaled);
      return;
    case SimdIsa::kAvx2:
      crack_avx2<Law>(b, n, k, scaled);
      return;
#endif
    default:
      if (scaled) {
        baseline::crack_loop<V2, Law, true>(b, n, k);
      } else {
        baseline::crack_loop<V2, Law, false>(b, n, k);
      }
  }
}

}  // namespace

void run_crack_batch(CrackBatch& b, int n, const CrackConstants& k, bool scaled, SimdIsa isa) {
  if (isa == SimdIsa::kBest) isa = resolved_simd_isa();
  with_crack_law(k.law, [&](auto law) { crack_isa<decltype(law)>(b, n, k, scaled, isa); });
}

}  // namespace rockfdem::fdem::detail
