// `rockfdem run [SCENE] -o DIR`: the whole pipeline, a tunnel's staged
// sequence (run_tunnel.cpp) or a specimen's loading (run_specimen.cpp).
#include "commands.hpp"
#include "interrupt.hpp"

namespace rockfdem::workflows {

int command_run(const Scene& scene, const CommandLine& cli) {
  install_interrupt_handlers();
  if (scene.mesh.kind == mesh::ModelKind::kUcs || scene.mesh.kind == mesh::ModelKind::kBrazilian)
    return run_specimen(scene, cli);
  return run_tunnel(scene, cli);
}

}  // namespace rockfdem::workflows
