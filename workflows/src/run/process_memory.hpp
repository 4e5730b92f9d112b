// What the process gives back to the system, and when. A run's phases use
// different libraries and arrays one after the other (gmsh, then deal.II and
// PETSc, then the engine): what one phase freed should not stay resident
// under the next one's peak.
#pragma once

#include "rockfdem/insitu/insitu.hpp"

namespace rockfdem::workflows {

/// glibc's own policy for large blocks, which a library switches off as it
/// is loaded (SuperLU_DIST, under PETSc: no block mapped apart, the heap
/// never trimmed). Blocks of 1 MiB and more are mapped apart, so that they
/// go back to the system when freed instead of leaving holes in the heap
/// that later phases cannot always reuse. Call once at the start of main.
void restore_malloc_policy();

/// The heap's free pages, wherever they lie in it, given back.
void release_free_heap();

/// `spec` with the code pages each field's solve ran (deal.II's assembly,
/// GAMG's set-up) given back once the field is out: the next alpha maps
/// again from the page cache what it runs, so the stage's peak, at its
/// last alpha, does not also hold what every earlier one touched.
insitu::InsituSpec returning_code_pages(insitu::InsituSpec spec);

/// At the end of a phase whose library the later phases do not call: the
/// freed heap and the clean pages of the library's code go back. A code
/// page used again is mapped from the page cache on first touch.
void release_phase_memory();

}  // namespace rockfdem::workflows
