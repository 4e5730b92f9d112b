// The error kinds that cross library boundaries. `rockfdem` maps them to
// exit codes once, in main(): InputError -> 2, NumericalError -> 3,
// OutputError (like any other error) -> 1.
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

/// An output that could not be written (disk full, no permission, a
/// missing folder): the message names the file and the system's reason. A
/// run that meets one records the failure in summary.json where it can.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace rockfdem
