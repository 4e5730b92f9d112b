#include "study/study_variants.hpp"

#include <cctype>
#include <cstdio>
#include <functional>
#include <numeric>
#include <random>
#include <set>

#include "scene/scene_reader.hpp"

namespace rockfdem::workflows::study {
namespace {

constexpr std::uint64_t kLatinSeed = 20261202;
constexpr std::size_t kLongestName = 160;

std::string sanitised(const std::string& text) {
  std::string s = text;
  for (char& c : s) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (!std::isalnum(u) && c != '.' && c != '+' && c != '=' && c != '-' && c != '_') c = '-';
  }
  return s;
}

// A uniform number in [0, 1) from the generator's 53 high bits: the same on
// every standard library (std::uniform_real_distribution is not).
double unit(std::mt19937_64& g) { return double(g() >> 11) * 0x1.0p-53; }

// Fisher-Yates with the generator's raw output, for the same reason.
std::vector<long> permutation(long n, std::mt19937_64& g) {
  std::vector<long> p(std::size_t(n), 0);
  std::iota(p.begin(), p.end(), 0L);
  for (long i = n - 1; i > 0; --i) std::swap(p[std::size_t(i)], p[g() % std::uint64_t(i + 1)]);
  return p;
}

}  // namespace

std::string exact_text(double v) { return detail::number_text(v); }

std::vector<std::string> Variant::overrides() const {
  std::vector<std::string> o;
  for (const auto& [key, value] : settings) o.push_back(key + "=" + value);
  return o;
}

Variant make_variant(std::vector<std::pair<std::string, std::string>> settings) {
  Variant v;
  v.settings = std::move(settings);
  std::string joined;
  for (const std::string& o : v.overrides()) joined += (joined.empty() ? "" : "_") + o;
  v.name = sanitised(joined);
  if (v.name.size() > kLongestName) {
    char hash[24];
    std::snprintf(hash, sizeof hash, "-%016zx", std::hash<std::string>{}(joined));
    v.name = v.name.substr(0, kLongestName - 17) + hash;
  }
  return v;
}

std::vector<Variant> product_variants(const std::vector<VariedKey>& keys) {
  std::size_t n = 1;
  for (const VariedKey& k : keys) n *= k.values.size();
  std::vector<Variant> variants;
  std::set<std::string> names;
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<std::pair<std::string, std::string>> settings(keys.size());
    std::size_t rest = i;
    for (std::size_t k = keys.size(); k-- > 0;) {
      settings[k] = {keys[k].key, keys[k].values[rest % keys[k].values.size()]};
      rest /= keys[k].values.size();
    }
    variants.push_back(make_variant(std::move(settings)));
    // Two values the sanitising makes alike ("a/b", "a-b") must not share a folder.
    if (!names.insert(variants.back().name).second) variants.back().name += "-" + std::to_string(i);
  }
  return variants;
}

std::vector<Variant> latin_hypercube(const std::vector<VariedKey>& keys, long samples) {
  std::mt19937_64 g(kLatinSeed);
  std::vector<std::vector<double>> values(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const std::vector<long> strata = permutation(samples, g);
    for (long i = 0; i < samples; ++i) {
      const double u = (double(strata[std::size_t(i)]) + unit(g)) / double(samples);
      values[k].push_back(keys[k].lo + u * (keys[k].hi - keys[k].lo));
    }
  }
  std::vector<Variant> variants;
  for (long i = 0; i < samples; ++i) {
    std::vector<std::pair<std::string, std::string>> settings;
    for (std::size_t k = 0; k < keys.size(); ++k)
      settings.push_back({keys[k].key, exact_text(values[k][std::size_t(i)])});
    variants.push_back(make_variant(std::move(settings)));
  }
  return variants;
}

std::vector<Variant> crossed(const std::vector<Variant>& variants, const VariedKey& list) {
  std::vector<Variant> all;
  for (const Variant& v : variants)
    for (const std::string& value : list.values) {
      std::vector<std::pair<std::string, std::string>> settings = v.settings;
      settings.push_back({list.key, value});
      all.push_back(make_variant(std::move(settings)));
    }
  return all;
}

}  // namespace rockfdem::workflows::study
