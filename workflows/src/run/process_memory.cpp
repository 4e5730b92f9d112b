// Why: SuperLU_DIST's start-up code (loaded with PETSc) sets M_MMAP_MAX to 0
// and M_TRIM_THRESHOLD to -1 for the whole process (found with a breakpoint
// on mallopt). Every block then lives in the one heap and the heap never
// shrinks: at 420k triangles the explicit stage held 448 MiB resident for
// 340 MiB in use, the rest holes left by the implicit stage and by the
// engine's set-up.
#include "run/process_memory.hpp"

#include <utility>

#include "run/loader_pages.hpp"

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace rockfdem::workflows {

void restore_malloc_policy() {
#ifdef __GLIBC__
  constexpr int kLargeBlock = 1 << 20;  // fixed: glibc's own threshold drifts up to 32 MiB
  mallopt(M_MMAP_MAX, 65536);           // glibc's default
  mallopt(M_MMAP_THRESHOLD, kLargeBlock);
  mallopt(M_TRIM_THRESHOLD, kLargeBlock);
#endif
}

void release_free_heap() {
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

insitu::InsituSpec returning_code_pages(insitu::InsituSpec spec) {
  spec.on_field = [own = std::move(spec.on_field)](insitu::InsituField& f) {
    if (own) own(f);
    release_loader_pages();
  };
  return spec;
}

void release_phase_memory() {
  release_free_heap();
  release_loader_pages();
}

}  // namespace rockfdem::workflows
