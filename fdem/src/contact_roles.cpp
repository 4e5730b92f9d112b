// run_roles: the narrow phase's per-edge arithmetic over a batch of roles
// (contact_roles.hpp; the mathematics is in contact_force.cpp's header, the
// kernel in contact_roles_kernel.hpp). This file instantiates the kernel
// for each instruction set and picks the widest the processor has.
#include "contact_roles.hpp"

#include <cstdlib>
#include <cstring>

#include "rockfdem/error.hpp"

namespace rockfdem::fdem::detail {
namespace {

#define ROCKFDEM_ISA_KERNEL "contact_roles_kernel.hpp"
#include "isa_regions.hpp"

void roles_baseline(PairBatch& b, int n, const RoleParams& rp) {
  baseline::roles_body<V2>(b, n, rp);
}

#if defined(__x86_64__)
__attribute__((target("avx512f,avx512dq"))) void roles_avx512(PairBatch& b, int n,
                                                              const RoleParams& rp) {
  avx512::roles_body<V8>(b, n, rp);
}
__attribute__((target("avx2"))) void roles_avx2(PairBatch& b, int n, const RoleParams& rp) {
  avx2::roles_body<V4>(b, n, rp);
}
bool has_avx512() {
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq");
}
bool has_avx2() { return __builtin_cpu_supports("avx2"); }
#else  // other processors: the baseline build of the loop (their own vector width)
void roles_avx512(PairBatch& b, int n, const RoleParams& rp) { roles_baseline(b, n, rp); }
void roles_avx2(PairBatch& b, int n, const RoleParams& rp) { roles_baseline(b, n, rp); }
bool has_avx512() { return false; }
bool has_avx2() { return false; }
#endif

/// The widest set the processor has, or a narrower one that the
/// environment variable ROCKFDEM_ISA (sse2, avx2, avx512) asks for, for
/// the contact and crack kernels alike: the results are the same bits,
/// only the speed differs (bench_contact measures each). A set the processor lacks falls back to
/// the widest it has; an unknown name is an input error (check_role_isa_request).
RoleIsa resolve_isa() {
  RoleIsa isa = has_avx512() ? RoleIsa::kAvx512 : has_avx2() ? RoleIsa::kAvx2 : RoleIsa::kBaseline;
  if (const char* ask = std::getenv("ROCKFDEM_ISA")) {
    if (std::strcmp(ask, "sse2") == 0)
      isa = RoleIsa::kBaseline;
    else if (std::strcmp(ask, "avx2") == 0 && isa == RoleIsa::kAvx512)
      isa = RoleIsa::kAvx2;
  }
  return isa;
}

/// Resolved once, at the first call (check_role_isa_request makes that a
/// serial one, before any parallel contact pass).
RoleIsa best_isa() {
  static const RoleIsa best = resolve_isa();
  return best;
}

}  // namespace

bool role_isa_available(RoleIsa isa) {
  switch (isa) {
    case RoleIsa::kAvx512:
      return has_avx512();
    case RoleIsa::kAvx2:
      return has_avx2();
    default:
      return true;
  }
}

void run_roles(PairBatch& b, int n, const RoleParams& rp, RoleIsa isa) {
  switch (isa == RoleIsa::kBest ? best_isa() : isa) {
    case RoleIsa::kAvx512:
      roles_avx512(b, n, rp);
      break;
    case RoleIsa::kAvx2:
      roles_avx2(b, n, rp);
      break;
    default:
      roles_baseline(b, n, rp);
      break;
  }
}

void run_roles(PairBatch& b, int n, const RoleParams& rp) { run_roles(b, n, rp, RoleIsa::kBest); }

const char* role_isa_name() {
  switch (best_isa()) {
    case RoleIsa::kAvx512:
      return "avx512";
    case RoleIsa::kAvx2:
      return "avx2";
    default:
#if defined(__x86_64__)
      return "sse2";
#else
      return "baseline";
#endif
  }
}

RoleIsa resolved_role_isa() { return best_isa(); }

void check_role_isa_request() {
  if (const char* ask = std::getenv("ROCKFDEM_ISA")) {
    if (std::strcmp(ask, "sse2") != 0 && std::strcmp(ask, "avx2") != 0 &&
        std::strcmp(ask, "avx512") != 0)
      throw InputError(std::string("environment: ROCKFDEM_ISA = '") + ask +
                       "': allowed sse2, avx2, avx512 (the widest instruction set the engine's "
                       "vector kernels may use), or unset");
  }
  best_isa();
}

}  // namespace rockfdem::fdem::detail
