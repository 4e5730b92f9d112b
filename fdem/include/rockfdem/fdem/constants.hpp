// Mathematical constants of the engine, defined once (M_PI is not standard
// C++).
#pragma once

namespace rockfdem::fdem {

/// pi to double precision.
inline constexpr double kPi = 3.14159265358979323846;

}  // namespace rockfdem::fdem
