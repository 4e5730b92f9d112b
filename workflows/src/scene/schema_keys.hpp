// Builders of the schema's key entries, for scene_schema.cpp and for the
// stages that bring their own keys (Stage::keys).
#pragma once

#include <string>
#include <vector>

#include "rockfdem/workflows/scene_schema.hpp"

namespace rockfdem::workflows::schema {

/// A number in [min, max] (an open end excludes the bound).
KeySpec number(std::string path, std::string unit, std::string def, double min, bool min_open,
               double max, bool max_open, std::string what);
/// A number > 0.
KeySpec positive(std::string path, std::string unit, std::string def, std::string what);
/// A number >= 0.
KeySpec non_negative(std::string path, std::string unit, std::string def, std::string what);
KeySpec integer(std::string path, std::string def, double min, double max, std::string what);
KeySpec choice(std::string path, std::string def, std::vector<std::string> choices,
               std::string what);
KeySpec text(std::string path, std::string def, std::string what);
KeySpec boolean(std::string path, std::string def, std::string what);

}  // namespace rockfdem::workflows::schema
