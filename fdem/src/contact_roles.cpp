// run_roles: the narrow phase's per-edge arithmetic over a batch of roles
// (contact_roles.hpp; the mathematics is in contact_force.cpp's header, the
// kernel in contact_roles_kernel.hpp). This file instantiates the kernel
// for each instruction set; simd_isa.hpp picks one.
#include "contact_roles.hpp"

namespace rockfdem::fdem::detail {
namespace {

#define ROCKFDEM_ISA_KERNEL "contact_roles_kernel.hpp"
#include "isa_regions.hpp"

#if defined(__x86_64__)
__attribute__((target("avx512f,avx512dq"))) void roles_avx512(PairBatch& b, int n,
                                                              const RoleParams& rp) {
  avx512::roles_body<V8>(b, n, rp);
}
__attribute__((target("avx2"))) void roles_avx2(PairBatch& b, int n, const RoleParams& rp) {
  avx2::roles_body<V4>(b, n, rp);
}
#endif

}  // namespace

void run_roles(PairBatch& b, int n, const RoleParams& rp, SimdIsa isa) {
  switch (isa == SimdIsa::kBest ? resolved_simd_isa() : isa) {
#if defined(__x86_64__)
    case SimdIsa::kAvx512:
      roles_avx512(b, n, rp);
      return;
    case SimdIsa::kAvx2:
      roles_avx2(b, n, rp);
      return;
#endif
    default:
      baseline::roles_body<V2>(b, n, rp);
  }
}

}  // namespace rockfdem::fdem::detail
