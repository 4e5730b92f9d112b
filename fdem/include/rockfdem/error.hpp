// The two error kinds that cross library boundaries. `rockfdem` maps them to
// exit codes once, in main(): InputError -> 2, NumericalError -> 3.
#pragma once

#include <stdexcept>
#include <string>

namespace rockfdem {

/// Bad input: a scene key, a mesh file, a command-line value. The message
/// names the file, the key (or line), the value and what is allowed.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A run that went unstable: the message names step, element or node,
/// quantity and value.
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace rockfdem
