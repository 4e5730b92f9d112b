// lining: the lining ring installed stress-free in the deformed shape,
// bonded to the rock by the lining interface where the two faces are.
#include "rockfdem/coupling/lining_cracks.hpp"
#include "stages/stage.hpp"

namespace rockfdem::workflows {
namespace {

// Re-joins the crack elements between the lining and the rock with the
// interface's bond, intact where they are; returns how many.
long bond_lining(StageModel& m) {
  if (m.materials.lining_interface < 0) return 0;
  // Sprayed onto the rock as it is now: the bond starts intact where the
  // two faces are, whatever the rock's convergence so far.
  const std::vector<std::size_t> bond = coupling::lining_interface_cracks(m.engine, m.mesh);
  for (std::size_t c : bond) m.engine.rejoin_crack(c, m.materials.lining_interface);
  return long(bond.size());
}

class Lining : public Stage {
 public:
  const char* description() const override { return "install the lining ring stress-free"; }

  void check(StageCheck& c) const override {
    if (!c.scene.lining_ring)
      c.refuse(".kind",
               "the model has no lining ring (tunnel.lining_thickness, or a "
               "msh.zones group mapped to \"lining\")");
    if (c.order.lined || c.scene.insitu.lining_active)
      c.refuse(".kind", "the lining is installed once");
    c.order.lined = true;
  }

  StageChanges apply(StageModel& m, const StageSpec&) const override {
    // Stress-free in the deformed shape: the lining takes only later load.
    m.set_zone(mesh::kLining, true, fdem::ActivationReference::kCurrent);
    for (std::size_t t = 0; t < m.mesh.n_triangles(); ++t)
      if (m.mesh.zone[t] == mesh::kLining) m.engine.set_stiffness_factor(t, 1.0);
    m.lining_installed = true;
    StageChanges done;
    done.interface_cracks = bond_lining(m);
    return done;
  }

  bool installs_support() const override { return true; }
};

}  // namespace

std::unique_ptr<const Stage> make_lining_stage() { return std::make_unique<Lining>(); }

}  // namespace rockfdem::workflows
