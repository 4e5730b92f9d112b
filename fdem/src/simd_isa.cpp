// The vector kernels' instruction set (simd_isa.hpp): the widest the
// processor has, capped by ROCKFDEM_ISA for measurements.
#include "simd_isa.hpp"

#include <cstdlib>
#include <cstring>
#include <string>

#include "rockfdem/error.hpp"

namespace rockfdem::fdem::detail {
namespace {

#if defined(__x86_64__)
bool has_avx512() {
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq");
}
bool has_avx2() { return __builtin_cpu_supports("avx2"); }
#else  // other processors run the baseline build at their own width
bool has_avx512() { return false; }
bool has_avx2() { return false; }
#endif

/// The widest set the processor has, or a narrower one that ROCKFDEM_ISA
/// (sse2, avx2, avx512) asks for. A set the processor lacks falls back to
/// the widest it has; an unknown name is an input error
/// (check_simd_isa_request).
SimdIsa resolve() {
  SimdIsa isa = has_avx512() ? SimdIsa::kAvx512 : has_avx2() ? SimdIsa::kAvx2 : SimdIsa::kBaseline;
  if (const char* ask = std::getenv("ROCKFDEM_ISA")) {
    if (std::strcmp(ask, "sse2") == 0)
      isa = SimdIsa::kBaseline;
    else if (std::strcmp(ask, "avx2") == 0 && isa == SimdIsa::kAvx512)
      isa = SimdIsa::kAvx2;
  }
  return isa;
}

}  // namespace

bool simd_isa_available(SimdIsa isa) {
  switch (isa) {
    case SimdIsa::kAvx512:
      return has_avx512();
    case SimdIsa::kAvx2:
      return has_avx2();
    default:
      return true;
  }
}

/// Resolved once, at the first call (check_simd_isa_request makes that a
/// serial one, before any parallel pass).
SimdIsa resolved_simd_isa() {
  static const SimdIsa best = resolve();
  return best;
}

const char* simd_isa_name() {
  switch (resolved_simd_isa()) {
    case SimdIsa::kAvx512:
      return "avx512";
    case SimdIsa::kAvx2:
      return "avx2";
    default:
#if defined(__x86_64__)
      return "sse2";
#else
      return "baseline";
#endif
  }
}

void check_simd_isa_request() {
  if (const char* ask = std::getenv("ROCKFDEM_ISA")) {
    if (std::strcmp(ask, "sse2") != 0 && std::strcmp(ask, "avx2") != 0 &&
        std::strcmp(ask, "avx512") != 0)
      throw InputError(std::string("environment: ROCKFDEM_ISA = '") + ask +
                       "': allowed sse2, avx2, avx512 (the widest instruction set the engine's "
                       "vector kernels may use), or unset");
  }
  resolved_simd_isa();
}

}  // namespace rockfdem::fdem::detail
