#include "record/run_context.hpp"

#include <omp.h>

#include "rockfdem/workflows/cli.hpp"

namespace rockfdem::workflows {

RunContext run_context(const CommandLine& cli) {
  RunContext ctx;
  ctx.threads = cli.threads > 0 ? cli.threads : omp_get_num_procs();
  ctx.output_dir = cli.output_dir;
  ctx.quiet = cli.quiet;
  ctx.force = cli.force;
  ctx.restart = cli.restart;
  ctx.checkpoint_every = cli.checkpoint_every;
  ctx.force_dt = cli.force_dt;
  return ctx;
}

OmpThreads::OmpThreads(int threads) : threads_(threads) { omp_set_num_threads(threads_); }

OmpThreads::~OmpThreads() { omp_set_num_threads(threads_); }

}  // namespace rockfdem::workflows
