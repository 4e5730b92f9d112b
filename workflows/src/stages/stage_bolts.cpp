// bolts: every bolt of the scene installed stress-free (the steel strips
// and their grout bond made active in the rock as it is now).
#include "stages/stage.hpp"

namespace rockfdem::workflows {
namespace {

class Bolts : public Stage {
 public:
  const char* description() const override { return "install every bolt stress-free"; }

  void check(StageCheck& c) const override {
    if (c.scene.bolts.segments.empty())
      c.refuse(".kind", "the scene has no [[bolt]] or [[bolt_fan]]");
    if (c.order.bolted) c.refuse(".kind", "the bolts are installed once");
    c.order.bolted = true;
  }

  StageChanges apply(StageModel& m, const StageSpec&) const override {
    const fdem::BoltInstallReport r = fdem::install_bolts(m.engine, m.bolts);
    StageChanges done;
    done.bolts = long(m.bolts.specs.size());
    done.bolt_triangles = r.triangles;
    done.steel_cracks = r.steel_cracks;
    done.grout_cracks = r.grout_cracks;
    return done;
  }

  bool installs_support() const override { return true; }
};

}  // namespace

std::unique_ptr<const Stage> make_bolts_stage() { return std::make_unique<Bolts>(); }

}  // namespace rockfdem::workflows
