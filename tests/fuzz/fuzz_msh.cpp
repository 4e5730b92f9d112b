// libFuzzer driver: bytes -> a temporary .msh file -> read_msh.
//
//   bash bench/fuzz.sh 600        # builds with clang, runs each driver
//
// The contract under test: any file either reads as a Mesh or throws
// rockfdem::InputError naming the file; never a crash, a hang, a sanitizer
// report or any other exception. Each input is read twice: with empty group
// maps (the names write_msh uses) and with named groups, as a scene's
// [msh] zones/edges would give them.
//
// By default each input is read in this process (detail::read_msh_in_process):
// libFuzzer sees the coverage of our checks after gmsh's read, and a crash
// inside gmsh is a finding (read_msh answers it as an InputError from its
// child process, but a new crash site is worth knowing). FUZZ_MSH_CHILD=1
// reads through read_msh itself, child process and record included.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

#include "msh_read.hpp"
#include "only_input_error.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/mesh/msh_io.hpp"

namespace {

const std::string& temp_path() {
  // gmsh chooses its reader by extension, so the name ends in .msh.
  static const std::string path = [] {
    const char* dir = std::getenv("TMPDIR");
    return std::string(dir && *dir ? dir : "/tmp") + "/rockfdem_fuzz_" + std::to_string(getpid()) +
           ".msh";
  }();
  return path;
}

void read_one(const rockfdem::mesh::MshFileSpec& spec) {
  static const bool child = [] {
    const char* v = std::getenv("FUZZ_MSH_CHILD");
    return v && std::string(v) == "1";
  }();
  rockfdem::fuzz::only_input_error(
      "fuzz_msh",
      [&] {
        (void)(child ? rockfdem::mesh::read_msh(spec)
                     : rockfdem::mesh::detail::read_msh_in_process(spec));
      },
      spec.path);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  {
    std::ofstream out(temp_path(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  using rockfdem::mesh::MshFileSpec;
  read_one(MshFileSpec{temp_path(), {}, {}, "", {}});
  // The groups of the hand-written square in tests/mesh/msh_io_test.cpp,
  // plus a fracture group.
  using namespace rockfdem::mesh;
  read_one(MshFileSpec{temp_path(), {{"granite", kRock}}, {{"base", kBottom}}, "granite", {}});
  return 0;
}
