#include "scene/stage_damping.hpp"

#include "rockfdem/workflows/scene_schema.hpp"

namespace rockfdem::workflows {

fdem::DampingSettings stage_damping(const Scene& s) {
  fdem::DampingSettings d;
  d.local = s.engine.local_damping >= 0 ? s.engine.local_damping : kTunnelLocalDamping;
  d.mass_proportional = s.engine.mass_damping;
  d.kinetic = s.engine.kinetic_damping;
  return d;
}

}  // namespace rockfdem::workflows
