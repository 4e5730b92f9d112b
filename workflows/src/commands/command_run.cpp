// `rockfdem run [SCENE] -o DIR`: the whole pipeline, a tunnel's staged
// sequence (run.cpp) or a specimen's loading (run_specimen.cpp).
#include "commands/commands.hpp"
#include "run/interrupt.hpp"
#include "run/run.hpp"

namespace rockfdem::workflows {

int command_run(const Scene& scene, const RunContext& ctx) {
  install_interrupt_handlers();
  const OmpThreads keep(ctx.threads);  // a study's variants each bring their own
  if (scene.mesh.kind == mesh::ModelKind::kUcs || scene.mesh.kind == mesh::ModelKind::kBrazilian)
    return run_specimen(scene, ctx);
  return run_tunnel(scene, ctx);
}

}  // namespace rockfdem::workflows
