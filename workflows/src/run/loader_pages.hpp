#pragma once

#include <cstddef>

namespace rockfdem::workflows {

/// Drops from the process's resident set the clean, never-written pages of
/// its mapped files (the libraries' symbol tables, relocations and start-up
/// code the loader read), and returns how many bytes it dropped. A page used
/// later is mapped again from the page cache on first touch; pages a
/// process wrote (relocated data, anything copied on write) are left alone.
std::size_t release_loader_pages();

}  // namespace rockfdem::workflows
