// remove_core: the core excavated (its triangles leave the model, keeping
// their reference), with a ring never installed, ground still to be dug.
#include "stages/stage.hpp"

namespace rockfdem::workflows {
namespace {

class RemoveCore : public Stage {
 public:
  void check(StageCheck& c) const override {
    if (!(c.order.alpha > 0)) c.refuse(".kind", "the core is already removed");
    c.order.alpha = 0;
  }

  StageChanges apply(StageModel& m, const StageSpec&) const override {
    m.set_zone(mesh::kCore, false, fdem::ActivationReference::kKeep);
    // A ring never installed is ground still to be excavated.
    if (!m.lining_installed) m.set_zone(mesh::kLining, false, fdem::ActivationReference::kKeep);
    m.core_present = false;
    return {};
  }

  std::string outcome(const StageRecord& record) const override {
    return record.converged ? Stage::outcome(record) : "core removed";
  }
};

}  // namespace

std::unique_ptr<const Stage> make_remove_core_stage() { return std::make_unique<RemoveCore>(); }

}  // namespace rockfdem::workflows
