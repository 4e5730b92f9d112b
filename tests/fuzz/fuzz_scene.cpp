// libFuzzer driver: scene text -> parse_scene (TOML parse, schema, validation).
//
//   bash bench/fuzz.sh 600        # builds with clang, runs each driver
//
// The contract under test: any input either gives a Scene or throws
// rockfdem::InputError; never a crash, a hang, a sanitizer report or any
// other exception. An input may carry --set overrides after a line "%%",
// one "section.key=value" per line, so the override parser is fuzzed too.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "only_input_error.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace {

// Splits "scene%%\noverride\noverride" into the scene and its overrides.
void split(const std::string& input, std::string& text, std::vector<std::string>& overrides) {
  const std::string mark = "\n%%\n";
  const auto at = input.find(mark);
  text = input.substr(0, at);
  if (at == std::string::npos) return;
  std::string rest = input.substr(at + mark.size());
  std::size_t begin = 0;
  while (begin <= rest.size()) {
    const auto end = rest.find('\n', begin);
    overrides.push_back(rest.substr(begin, end == std::string::npos ? end : end - begin));
    if (end == std::string::npos) break;
    begin = end + 1;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  std::string text;
  std::vector<std::string> overrides;
  split(input, text, overrides);
  // base_dir: a folder that does not exist, so msh.file keys are answered
  // "cannot open" unless they name an absolute path.
  rockfdem::fuzz::only_input_error("fuzz_scene", [&] {
    (void)rockfdem::workflows::parse_scene(text, "fuzz.toml", "/nonexistent-fuzz-dir", overrides);
  });
  return 0;
}
