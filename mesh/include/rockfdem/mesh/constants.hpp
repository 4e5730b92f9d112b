// Mathematical constants of the meshing stage, defined once (M_PI is not
// standard C++).
#pragma once

namespace rockfdem::mesh {

/// pi to double precision.
inline constexpr double kPi = 3.14159265358979323846;

}  // namespace rockfdem::mesh
