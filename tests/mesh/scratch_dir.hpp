// The mesh tests' files: in one directory per process (ctest runs a test
// file's tests in parallel processes, which must not write the same file),
// removed with everything in it when the process ends, so that a test run
// leaves nothing behind. Children that leave by _exit (msh_child, gtest's
// death tests) remove nothing.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace rockfdem::mesh::test {

class ScratchDir {
 public:
  ScratchDir() : dir_(::testing::TempDir() + "rockfdem_mesh_tests_" + std::to_string(::getpid())) {
    std::filesystem::create_directories(dir_);
  }
  ~ScratchDir() {
    std::error_code ignored;  // a destructor at exit has no one to tell
    std::filesystem::remove_all(dir_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  std::string path(const std::string& name) const { return dir_ + "/" + name; }

 private:
  std::string dir_;
};

/// `name` in this process's scratch directory.
inline std::string scratch_path(const std::string& name) {
  static const ScratchDir dir;
  return dir.path(name);
}

}  // namespace rockfdem::mesh::test
