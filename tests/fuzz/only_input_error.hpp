// The contract both fuzz drivers check: a call on bad input may throw
// rockfdem::InputError (whose message names `must_name`, when given) and
// nothing else. Anything else aborts, which libFuzzer records as a finding.
#pragma once

#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>
#include <typeinfo>

#include "rockfdem/error.hpp"

namespace rockfdem::fuzz {

template <class Call>
void only_input_error(const char* driver, Call call, const std::string& must_name = "") {
  try {
    call();
  } catch (const InputError& e) {
    if (std::string(e.what()).find(must_name) != std::string::npos) return;
    std::cerr << driver << ": InputError without '" << must_name << "': " << e.what() << "\n";
    std::abort();
  } catch (const std::exception& e) {
    std::cerr << driver << ": unexpected " << typeid(e).name() << ": " << e.what() << "\n";
    std::abort();
  } catch (...) {
    std::cerr << driver << ": unexpected exception of a type not derived from std::exception\n";
    std::abort();
  }
}

}  // namespace rockfdem::fuzz
