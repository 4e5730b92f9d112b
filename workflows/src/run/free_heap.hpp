// The heap's free pages given back to the system. In a run's process glibc
// neither maps large blocks apart nor trims the heap on its own
// (malloc_stats: no mmap region at all), so scratch freed after the
// engine was built stays resident: at 420k triangles 182 MB of a 519 MB
// heap during the explicit stage, most of it the stability limit's
// vectors and element bounds, recomputed at a stage's first step.
#pragma once

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace rockfdem::workflows {

inline void release_free_heap() {
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

}  // namespace rockfdem::workflows
