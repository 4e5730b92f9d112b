#include "rockfdem/fdem/bits_hash.hpp"

#include <cstdio>

namespace rockfdem::fdem {

std::uint64_t fnv1a(const void* data, std::size_t n_bytes) {
  std::uint64_t h = 1469598103934665603ull;  // offset basis
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < n_bytes; ++i) {
    h ^= bytes[i];
    h *= 1099511628211ull;  // FNV prime
  }
  return h;
}

std::string bits_hash(const std::vector<double>& values) {
  char buf[17];
  std::snprintf(
      buf, sizeof buf, "%016llx",
      static_cast<unsigned long long>(fnv1a(values.data(), values.size() * sizeof(double))));
  return buf;
}

}  // namespace rockfdem::fdem
