#include "study/study_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

#include "rockfdem/error.hpp"
#include "rockfdem/workflows/scene_schema.hpp"
#include "scene/scene_reader.hpp"
#include "study/study_figures.hpp"

namespace rockfdem::workflows::study {

const char* const kRealisationKey = "materials.rock.heterogeneity_seed";

namespace {

constexpr long kMostRealisations = 10000;

[[noreturn]] void refuse(const std::string& flag, const std::string& value,
                         const std::string& why) {
  throw InputError("command line: " + flag + " " + value + ": " + why);
}

// "KEY=REST" -> {KEY, REST}; refused without a key or a value.
std::pair<std::string, std::string> split(const std::string& flag, const std::string& text,
                                          const std::string& form) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    refuse(flag, text, "expected " + form);
  return {text.substr(0, eq), text.substr(eq + 1)};
}

bool parse_number(const std::string& text, double* v) {
  char* end = nullptr;
  *v = std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size() && std::isfinite(*v);
}

// A scene key that takes a real number (ranges are sampled continuously).
void check_number_key(const std::string& flag, const std::string& text, const std::string& key) {
  const KeySpec* spec = find_key(detail::normalise(key));
  if (!spec) refuse(flag, text, "unknown scene key '" + key + "'; see docs/scene-reference.md");
  if (spec->type != KeyType::kNumber)
    refuse(flag, text,
           "'" + key + "' is not a real-valued key; allowed: a number key (" +
               describe_allowed(*spec) + " is not sampled continuously)");
}

// "LO:HI" with finite numbers, LO < HI.
bool parse_range(const std::string& text, double* lo, double* hi) {
  const auto colon = text.find(':');
  return colon != std::string::npos && parse_number(text.substr(0, colon), lo) &&
         parse_number(text.substr(colon + 1), hi);
}

void check_unique(const std::string& flag, const std::string& text, const std::string& key,
                  std::set<std::string>& seen) {
  if (!seen.insert(key).second) refuse(flag, text, "'" + key + "' is given twice");
}

VariedKey read_one_vary(const std::string& text, bool sampled) {
  const auto [key, rest] =
      split("--vary", text, sampled ? "KEY=LO:HI (with --samples)" : "KEY=V1,V2,...");
  VariedKey v;
  v.key = key;
  if (sampled) {
    check_number_key("--vary", text, key);
    if (!parse_range(rest, &v.lo, &v.hi) || !(v.lo < v.hi))
      refuse("--vary", text, "with --samples, allowed: KEY=LO:HI with finite numbers LO < HI");
    v.range = true;
    return v;
  }
  if (!find_key(detail::normalise(key)))
    refuse("--vary", text, "unknown scene key '" + key + "'; see docs/scene-reference.md");
  double lo = 0, hi = 0;
  if (parse_range(rest, &lo, &hi))
    refuse("--vary", text, "a range LO:HI needs --samples N; allowed without it: KEY=V1,V2,...");
  std::size_t start = 0;
  for (std::size_t comma = rest.find(','); start <= rest.size(); comma = rest.find(',', start)) {
    const std::string value = rest.substr(start, comma - start);
    if (value.empty()) refuse("--vary", text, "an empty value; allowed: KEY=V1,V2,...");
    v.values.push_back(value);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return v;
}

}  // namespace

std::vector<VariedKey> read_vary(const StudyOptions& options) {
  if (options.vary.empty() && (!options.realisations || options.samples != 0))
    throw InputError(
        "command line: `rockfdem sweep` needs at least one --vary KEY=V1,V2,... (or, without "
        "--samples, --realisations N)");
  if (options.samples < 0 || options.samples > 100000)
    refuse("--samples", std::to_string(options.samples), "allowed 1 to 100000");
  std::vector<VariedKey> keys;
  std::set<std::string> seen;
  for (const std::string& text : options.vary) {
    keys.push_back(read_one_vary(text, options.samples > 0));
    check_unique("--vary", text, keys.back().key, seen);
  }
  const VariedKey seeds = read_realisations(options);
  if (!seeds.values.empty()) {
    check_unique("--realisations", std::to_string(*options.realisations), seeds.key, seen);
    keys.push_back(seeds);
  }
  return keys;
}

std::vector<FreeKey> read_free(const StudyOptions& options) {
  if (options.free.empty())
    throw InputError("command line: `rockfdem calibrate` needs at least one --free KEY=LO:HI");
  std::vector<FreeKey> keys;
  std::set<std::string> seen;
  for (const std::string& text : options.free) {
    const auto [key, rest] = split("--free", text, "KEY=LO:HI");
    check_number_key("--free", text, key);
    FreeKey f{key, 0, 0};
    if (!parse_range(rest, &f.lo, &f.hi) || !(f.lo < f.hi))
      refuse("--free", text, "allowed: KEY=LO:HI with finite numbers LO < HI");
    check_unique("--free", text, key, seen);
    keys.push_back(f);
  }
  return keys;
}

std::vector<Target> read_targets(const StudyOptions& options, const Scene& scene) {
  if (options.targets.empty())
    throw InputError("command line: `rockfdem calibrate` needs at least one --target NAME=VALUE");
  const std::vector<TargetName> allowed = target_names(scene);
  std::vector<Target> targets;
  std::set<std::string> seen;
  for (const std::string& text : options.targets) {
    const auto [name, rest] = split("--target", text, "NAME=VALUE");
    const TargetName* known = find_target(allowed, name);
    if (!known) refuse("--target", text, "unknown name '" + name + "'; " + describe(allowed));
    Target t{name, known->column, 0, 1};
    if (!parse_number(rest, &t.value) || t.value == 0)
      refuse("--target", text,
             "allowed: a finite nonzero number in " + known->unit + " (misfits are relative)");
    check_unique("--target", text, name, seen);
    targets.push_back(t);
  }
  for (const std::string& text : options.weights) {
    const auto [name, rest] = split("--weight", text, "NAME=W");
    auto it = std::find_if(targets.begin(), targets.end(),
                           [&](const Target& t) { return t.name == name; });
    if (it == targets.end())
      refuse("--weight", text, "'" + name + "' is not one of the --target names");
    if (!parse_number(rest, &it->weight) || it->weight <= 0)
      refuse("--weight", text, "allowed: a finite number > 0");
  }
  return targets;
}

VariedKey read_realisations(const StudyOptions& options) {
  VariedKey seeds{kRealisationKey, {}, false, 0, 0};
  if (!options.realisations) return seeds;
  const long n = *options.realisations;
  if (n < 2 || n > kMostRealisations)
    refuse("--realisations", std::to_string(n),
           "allowed: a whole number of runs from 2 to " + std::to_string(kMostRealisations) +
               " (one per seed " + kRealisationKey + "=1..N)");
  for (long s = 1; s <= n; ++s) seeds.values.push_back(std::to_string(s));
  return seeds;
}

void check_realisations_differ(const StudyOptions& options, bool heterogeneous) {
  if (options.realisations && !heterogeneous)
    refuse("--realisations", std::to_string(*options.realisations),
           "materials.rock.heterogeneity is 0 (a homogeneous rock: every seed gives the same "
           "run); allowed only with a Weibull modulus > 0, e.g. --set "
           "materials.rock.heterogeneity=5");
}

bool heterogeneous_rock(const Scene& scene) {
  const auto rock = scene.materials.find(mesh::kRock);
  return rock != scene.materials.end() && rock->second.heterogeneity > 0;
}

Scene scene_with(const CommandLine& cli, const std::vector<std::string>& overrides,
                 const std::string& flag, const std::string& value) {
  std::vector<std::string> all = cli.overrides;
  all.insert(all.end(), overrides.begin(), overrides.end());
  try {
    return load_scene(cli.scene, all);
  } catch (const InputError& e) {
    refuse(flag, value, e.what());
  }
}

}  // namespace rockfdem::workflows::study
