// bolts: every bolt of the scene installed (the steel strips and their
// grout bond made active in the rock as it is now), stress-free or keeping
// the rock's stress (bolts.install_stress).
#include "stages/stage.hpp"

namespace rockfdem::workflows {
namespace {

class Bolts : public Stage {
 public:
  const char* description() const override {
    return "install every bolt, stress-free or keeping the rock's stress: bolts.install_stress";
  }

  void check(StageCheck& c) const override {
    if (c.scene.bolts.segments.empty())
      c.refuse(".kind", "the scene has no [[bolt]] or [[bolt_fan]]");
    if (c.order.bolted) c.refuse(".kind", "the bolts are installed once");
    c.order.bolted = true;
  }

  StageChanges apply(StageModel& m, const StageSpec&) const override {
    const fdem::BoltStart start = m.scene.bolts.keep_current_stress
                                      ? fdem::BoltStart::kKeepCurrentStress
                                      : fdem::BoltStart::kStressFree;
    const fdem::BoltInstallReport r = fdem::install_bolts(m.engine, m.bolts, start);
    StageChanges done;
    done.bolts = long(m.bolts.specs.size());
    done.bolt_triangles = r.triangles;
    done.steel_cracks = r.steel_cracks;
    done.grout_cracks = r.grout_cracks;
    if (start == fdem::BoltStart::kKeepCurrentStress) done.clipped_points = r.clipped_points;
    return done;
  }

  bool installs_support() const override { return true; }
};

}  // namespace

std::unique_ptr<const Stage> make_bolts_stage() { return std::make_unique<Bolts>(); }

}  // namespace rockfdem::workflows
