// What an engine bench program does around its work: print its command
// line, read "--name value" options, map the engine's errors to exit codes
// (2 input, 3 numerical). The older programs read their options themselves.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>
#include <variant>
#include <vector>

#include "rockfdem/error.hpp"

namespace rockfdem::bench {

struct Option {
  const char* name;
  std::variant<long*, int*, double*> value;
};

/// Prints the command line, then reads "--name value" pairs into `options`.
/// Returns false, after a usage line on stderr, on --help, an unknown
/// option or a missing value.
inline bool read_options(int argc, char** argv, const std::vector<Option>& options,
                         const char* usage) {
  std::printf("command:");
  for (int i = 0; i < argc; ++i) std::printf(" %s", argv[i]);
  std::printf("\n");
  for (int i = 1; i < argc; i += 2) {
    const std::string a = argv[i];
    const Option* found = nullptr;
    for (const Option& o : options) found = a == o.name ? &o : found;
    if (!found || i + 1 >= argc) {
      std::fprintf(stderr, "%s%s\nusage: %s\n", a == "--help" ? "" : "unknown option ",
                   a == "--help" ? "" : a.c_str(), usage);
      return false;
    }
    const char* text = argv[i + 1];
    std::visit(
        [text](auto* v) {
          using T = std::remove_pointer_t<decltype(v)>;
          *v = std::is_same_v<T, double> ? static_cast<T>(std::atof(text))
                                         : static_cast<T>(std::atol(text));
        },
        found->value);
  }
  return true;
}

/// Runs body() (returning the exit code) and maps the engine's errors.
template <class Body>
int run_guarded(Body body) {
  try {
    return body();
  } catch (const InputError& e) {
    std::fprintf(stderr, "input error: %s\n", e.what());
    return 2;
  } catch (const NumericalError& e) {
    std::fprintf(stderr, "numerical error: %s\n", e.what());
    return 3;
  }
}

}  // namespace rockfdem::bench
