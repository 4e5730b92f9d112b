// libFuzzer driver: bytes -> a temporary .msh file -> read_msh.
//
//   bash bench/fuzz.sh 600        # builds with clang, runs each driver
//
// The contract under test: any file either reads as a Mesh or throws
// rockfdem::InputError naming the file; never a crash, a hang, a sanitizer
// report or any other exception. Each input is read twice: with empty group
// maps (the names write_msh uses) and with named groups, as a scene's
// [msh] zones/edges would give them.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

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
  rockfdem::fuzz::only_input_error(
      "fuzz_msh", [&] { (void)rockfdem::mesh::read_msh(spec); }, spec.path);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  {
    std::ofstream out(temp_path(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  using rockfdem::mesh::MshFileSpec;
  read_one(MshFileSpec{temp_path(), {}, {}, ""});
  // The groups of the hand-written square in tests/mesh/msh_io_test.cpp,
  // plus a fracture group.
  using namespace rockfdem::mesh;
  read_one(MshFileSpec{temp_path(), {{"granite", kRock}}, {{"base", kBottom}}, "granite"});
  return 0;
}
