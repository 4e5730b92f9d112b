// libFuzzer driver: checkpoint bytes -> Engine::load_state.
//
//   bash bench/fuzz.sh 600 fuzz_checkpoint
//
// The contract under test: any bytes either load or throw
// rockfdem::InputError, and a failed load leaves the engine as it was;
// never a crash, a sanitizer report, an allocation beyond the input's size
// or any other exception. Random bytes stop at the checksum, so the driver
// first makes the header's length, fingerprint and the trailing checksum
// consistent with the input: mutations then reach the section parser.
//
// Seed: ROCKFDEM_FUZZ_SEED=FILE writes a real checkpoint of the driver's
// model (a fractured, contacting 4 x 4 block after 400 steps) and exits.
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "only_input_error.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/fdem/structured_mesh.hpp"

namespace {

using rockfdem::fdem::Engine;

rockfdem::fdem::ModelInput model() {
  rockfdem::fdem::RectangleSpec spec;
  spec.nx = spec.ny = 4;
  rockfdem::fdem::ModelInput in =
      rockfdem::fdem::ucs_specimen(spec, rockfdem::fdem::benchmark_rock(), 5.0);
  in.contact.enabled = true;
  in.threads = 1;
  return in;
}

Engine& engine() {
  static Engine e(model());
  return e;
}

std::uint64_t fnv1a(const char* p, std::size_t n) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::size_t i = 0; i < n; ++i) h = (h ^ static_cast<unsigned char>(p[i])) * 1099511628211ull;
  return h;
}

// Header offsets (checkpoint_format.hpp): length at 16, fingerprint at 24,
// FNV-1a of everything before the last 8 bytes at the end.
void make_consistent(std::string& b) {
  if (b.size() < 40) return;
  const std::uint64_t length = b.size(), fingerprint = engine().model_fingerprint();
  std::memcpy(&b[16], &length, 8);
  std::memcpy(&b[24], &fingerprint, 8);
  const std::uint64_t sum = fnv1a(b.data(), b.size() - 8);
  std::memcpy(&b[b.size() - 8], &sum, 8);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  if (const char* seed = std::getenv("ROCKFDEM_FUZZ_SEED")) {
    Engine e(model());
    e.run(400);
    std::ofstream out(seed, std::ios::binary);
    e.save_state(out);
    std::exit(out ? 0 : 1);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string bytes(reinterpret_cast<const char*>(data), size);
  make_consistent(bytes);
  const std::string before = engine().state_hash();
  std::istringstream in(bytes);
  bool loaded = false;
  rockfdem::fuzz::only_input_error("fuzz_checkpoint", [&] {
    engine().load_state(in);
    loaded = true;
  });
  if (!loaded && engine().state_hash() != before) {
    std::fputs("fuzz_checkpoint: a failed load changed the engine\n", stderr);
    std::abort();
  }
  return 0;
}
