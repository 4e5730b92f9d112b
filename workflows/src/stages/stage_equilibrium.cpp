// equilibrium: no change to the model; steps until the unbalanced-force
// ratio and the key points' settle measure both hold at `hold` consecutive
// outputs (Stage::step, the criterion every stepping stage but grout uses).
#include "stages/stage.hpp"

namespace rockfdem::workflows {
namespace {

class Equilibrium : public Stage {};

}  // namespace

std::unique_ptr<const Stage> make_equilibrium_stage() { return std::make_unique<Equilibrium>(); }

}  // namespace rockfdem::workflows
