// The runs of a study: each a set of scene keys and values, named by them.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "study/study_inputs.hpp"

namespace rockfdem::workflows::study {

struct Variant {
  std::string name;  ///< folder under <out>/variants/: "key=value_key=value", sanitised
  std::vector<std::pair<std::string, std::string>> settings;  ///< key, value text
  /// The settings as --set strings.
  std::vector<std::string> overrides() const;
};

/// A variant of these settings, named deterministically by them: each
/// "key=value", joined by '_', with characters outside [A-Za-z0-9._+=-]
/// replaced by '-'; a name over 160 characters is cut and ends in a hash
/// of the settings.
Variant make_variant(std::vector<std::pair<std::string, std::string>> settings);

/// Every combination of the lists, the last key varying fastest.
std::vector<Variant> product_variants(const std::vector<VariedKey>& keys);

/// `samples` Latin hypercube points over the ranges: each range cut into
/// `samples` equal strata, one point per stratum per key, the strata paired
/// by permutations drawn from a Mersenne Twister with a fixed seed (so the
/// same flags give the same variants on any machine and any rank count).
std::vector<Variant> latin_hypercube(const std::vector<VariedKey>& keys, long samples);

/// Each variant once per value of `list` (its key added last), the list
/// varying fastest: the realisations of each variant.
std::vector<Variant> crossed(const std::vector<Variant>& variants, const VariedKey& list);

/// Numbers in variant names and CSV cells: the shortest text that reads back
/// as the same double.
std::string exact_text(double v);

}  // namespace rockfdem::workflows::study
