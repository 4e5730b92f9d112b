// What the scene reader needs of a stage kind: its keys, its check of a
// [[stages]] entry against the entries before it, and whether it installs
// support. The scene owns this interface; the stages (stages/stage.hpp)
// implement it and their registry (stages/registry.cpp) answers the
// lookups declared here, so scene/ never includes stages/.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rockfdem/workflows/scene.hpp"
#include "rockfdem/workflows/scene_schema.hpp"

namespace rockfdem::workflows {

/// What the stages before an entry of [[stages]] allow, as the scene
/// reader walks the list in order.
struct StageOrder {
  double alpha = 0;     ///< the core's stiffness factor (0: removed)
  bool lined = false;   ///< a lining stage came before
  bool bolted = false;  ///< a bolts stage came before
};

/// One [[stages]] entry being read: the scene read so far, the entry and
/// the order before it. Keys are the entry's own (".alpha", ".kind").
class StageCheck {
 public:
  StageCheck(const Scene& s, const StageSpec& e, StageOrder& o) : scene(s), spec(e), order(o) {}
  virtual ~StageCheck() = default;
  /// Throws the scene's InputError naming the entry's `key` and `why`.
  [[noreturn]] virtual void refuse(const std::string& key, const std::string& why) const = 0;
  /// Refuses the entry when the file does not give `key`.
  virtual void require(const std::string& key, const std::string& why) const = 0;

  const Scene& scene;
  const StageSpec& spec;
  StageOrder& order;
};

/// One [[stages]] entry's keys as its kind reads them (".alpha"): whether
/// the file gives one, and its value or the schema's default.
class StageEntry {
 public:
  virtual bool has(const std::string& key) const = 0;
  virtual double number(const std::string& key) const = 0;

 protected:
  ~StageEntry() = default;
};

class StageKind {
 public:
  virtual ~StageKind() = default;
  /// What the stage does, in a few words for the scene reference ("" for
  /// a kind its name says all of).
  virtual const char* description() const { return ""; }
  /// The scene keys the stage reads beyond stages[] (scene_schema() lists
  /// them where the reference has them); none by default.
  virtual std::vector<KeySpec> keys() const { return {}; }
  /// The keys of a [[stages]] entry that this kind alone reads
  /// ("stages[].alpha"), listed in the schema after the keys every entry
  /// has; an entry of another kind that gives one is refused.
  virtual std::vector<KeySpec> entry_keys() const { return {}; }
  /// Reads the entry's own keys (entry_keys) into the kind's own values
  /// (StageSpec::own); none by default. A kind with values of its own
  /// derives from StageWithValues (stages/stage.hpp), which reads them back.
  virtual std::shared_ptr<const StageValues> read(const StageEntry&) const { return nullptr; }
  /// The entry's own values in a few words, for the notes that list the
  /// stages (the mesh preview): "to alpha 0.3"; none by default.
  virtual std::string note(const StageSpec&) const { return ""; }
  /// Refuses an entry the stages before it (or the scene) do not allow,
  /// and notes in check.order what it changes; allows any by default.
  virtual void check(StageCheck&) const {}
  /// Whether the stage installs support: the instruments' and plots'
  /// origin of what the support measures.
  virtual bool installs_support() const { return false; }
};

/// The kind registered as `kind`; std::logic_error when none is (a
/// validated scene names only registered kinds).
const StageKind& stage_kind(const std::string& kind);
/// The registered kinds, built-in first, in the order of the reference.
std::vector<std::string> stage_kinds();
/// The kinds with their one-line descriptions, as the scene reference
/// lists them: "`soften` (core to alpha, explicit), ..., `equilibrium`".
std::string stage_kind_descriptions();

}  // namespace rockfdem::workflows
