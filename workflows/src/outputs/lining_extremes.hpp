// The ring's section force extremes an engineer designs with, and those at
// its corners apart (docs/support.md, "Lining forces").
//
//        arch and walls                 A horseshoe's ring turns sharply
//      .-~~~~~~~~~~~~~-.                where the walls meet the floor (x):
//     /                 \               the segments there (corner, in
//    |                   |              lining_forces.hpp) are no beam
//    x-------------------x              section, their forces stress
//          invert                       concentrations; the extremes of
//                                       the others are the design figures.
#pragma once

#include <optional>
#include <vector>

#include "outputs/lining_forces.hpp"

namespace rockfdem::workflows {

/// One extreme: its value and the segment it is at.
struct SegmentExtreme {
  double value = 0;  ///< in the forces' unit (N/m, N m/m)
  std::size_t segment = 0;
};

/// The largest thrust, the smallest (tension when negative), the largest
/// |moment| and the largest |shear| of a set of segments.
struct ForceExtremes {
  SegmentExtreme max_thrust, min_thrust, max_abs_moment, max_abs_shear;
};

struct LiningExtremes {
  /// Of the segments that are beam sections (every segment when all are
  /// corners).
  ForceExtremes sections;
  /// Of the corner segments; none without corners.
  std::optional<ForceExtremes> corners;
  /// The corners' largest thrust, largest |moment| or tension passes the
  /// sections': the corners' figures say something the sections' do not.
  bool corners_exceed = false;
};

/// The extremes of forces `f` (one per segment of `g`).
LiningExtremes lining_extremes(const LiningGeometry& g, const std::vector<SectionForces>& f);

}  // namespace rockfdem::workflows
