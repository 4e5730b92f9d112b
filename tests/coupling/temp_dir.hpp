// A fresh directory per test, removed afterwards (kept, and its path
// printed, when ROCKFDEM_KEEP_TEST_FILES is set: for looking at the output).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <set>
#include <string>

namespace rockfdem::coupling::testing {

class TempDir {
 public:
  TempDir() {
    std::string tmpl =
        (std::filesystem::temp_directory_path() / "rockfdem-coupling-XXXXXX").string();
    if (!::mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed");
    path_ = tmpl;
  }
  ~TempDir() {
    if (std::getenv("ROCKFDEM_KEEP_TEST_FILES")) {
      std::cerr << "kept test files in " << path_ << "\n";
      return;
    }
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }

  /// Names of everything in the directory: how the tests see stray temp files.
  std::set<std::string> entries() const {
    std::set<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(path_)) {
      names.insert(e.path().filename().string());
    }
    return names;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace rockfdem::coupling::testing
