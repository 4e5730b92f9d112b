#include "stages/registry.hpp"

#include <stdexcept>
#include <utility>

#include "stages/stage.hpp"

namespace rockfdem::workflows {

// One line per built-in stage kind, in the reference's order: the kind is
// the scene keyword, and stage_<kind>.cpp defines make_<kind>_stage().
// Named here, so the linker keeps each stage's object file.
#define ROCKFDEM_BUILTIN_STAGES(STAGE) \
  STAGE(soften)                        \
  STAGE(lining)                        \
  STAGE(bolts)                         \
  STAGE(remove_core)                   \
  STAGE(grout)                         \
  STAGE(equilibrium)                   \
  STAGE(load_platens)

#define ROCKFDEM_DECLARE_STAGE(kind) std::unique_ptr<const Stage> make_##kind##_stage();
ROCKFDEM_BUILTIN_STAGES(ROCKFDEM_DECLARE_STAGE)

using RegisteredStage = std::pair<std::string, std::unique_ptr<const Stage>>;

static std::vector<RegisteredStage> builtin_stages() {
  std::vector<RegisteredStage> s;
#define ROCKFDEM_ADD_STAGE(kind) s.emplace_back(#kind, make_##kind##_stage());
  ROCKFDEM_BUILTIN_STAGES(ROCKFDEM_ADD_STAGE)
  return s;
}

// Made on first use, from whichever translation unit asks first.
static std::vector<RegisteredStage>& registry() {
  static std::vector<RegisteredStage> entries = builtin_stages();
  return entries;
}

void register_stage(const std::string& kind, std::unique_ptr<const Stage> stage) {
  for (const RegisteredStage& e : registry())
    if (e.first == kind) throw std::logic_error("stage kind '" + kind + "' registered twice");
  registry().emplace_back(kind, std::move(stage));
}

const Stage& stage_of(const std::string& kind) {
  for (const RegisteredStage& e : registry())
    if (e.first == kind) return *e.second;
  throw std::logic_error("no stage of kind '" + kind + "' is registered");
}

const StageKind& stage_kind(const std::string& kind) { return stage_of(kind); }

std::vector<std::string> stage_kinds() {
  std::vector<std::string> kinds;
  for (const RegisteredStage& e : registry()) kinds.push_back(e.first);
  return kinds;
}

std::string stage_kind_descriptions() {
  std::string out;
  for (const RegisteredStage& e : registry()) {
    const std::string what = e.second->description();
    out += (out.empty() ? "`" : ", `") + e.first + '`' + (what.empty() ? "" : " (" + what + ")");
  }
  return out;
}

}  // namespace rockfdem::workflows
