// Runs the rockfdem binary as a user does, for the command-line tests.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace rockfdem::test {

struct Result {
  int code = -1;
  std::string output;
};

/// `rockfdem ARGS` with stderr merged into the output; `prefix` runs it
/// through another command (`env -u DISPLAY`, `xvfb-run -a`).
inline Result run(const std::string& args, const std::string& prefix = "") {
  Result r;
  const std::string cmd = prefix + " " + std::string(ROCKFDEM_BINARY) + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf{};
  while (std::fgets(buf.data(), buf.size(), pipe)) r.output += buf.data();
  const int status = pclose(pipe);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

/// A fresh (absent) scratch path under the temp directory, unique per process.
inline std::filesystem::path scratch(const std::string& name) {
  std::filesystem::path p = std::filesystem::temp_directory_path() /
                            ("rockfdem-cli-" + name + "-" + std::to_string(getpid()));
  std::filesystem::remove_all(p);
  return p;
}

inline nlohmann::json read_json(const std::filesystem::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

const std::string kTestDir = ROCKFDEM_TEST_DIR;

}  // namespace rockfdem::test
