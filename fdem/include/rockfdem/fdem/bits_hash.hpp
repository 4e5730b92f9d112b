// FNV-1a 64: the hash behind summary.json's state_hash (equal hashes mean
// bit-identical values) and the checkpoints' checksums.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rockfdem::fdem {

/// FNV-1a 64 of `n_bytes` bytes.
std::uint64_t fnv1a(const void* data, std::size_t n_bytes);

/// fnv1a of the values' bytes (native order), as 16 lower-case hex digits.
std::string bits_hash(const std::vector<double>& values);

}  // namespace rockfdem::fdem
