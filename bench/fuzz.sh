#!/usr/bin/env bash
# Fuzz the scene parser, the .msh reader and the engine's checkpoint reader with libFuzzer (clang-14 from
# Debian), each for a fixed time, and print the figures docs/reliability.md
# records (executions, corpus size, findings).
#
#   bash bench/fuzz.sh [SECONDS] [DRIVER...]    # default: 600 s, fuzz_scene fuzz_msh
#
# Build: build-fuzz/ (clang++-14; libraries with -fsanitize=fuzzer-no-link
# plus ASan/UBSan, drivers with -fsanitize=fuzzer). Seeds: tests/fuzz/make_corpus.sh.
# Corpora grow in build-fuzz/corpus/<driver>/; crashes, hangs (-timeout) and
# out-of-memory inputs land in build-fuzz/findings/<driver>/. A finding is
# fixed, then kept as a regression test (tests/workflows/bad_scenes/ or
# tests/mesh/msh_io_test.cpp), never as a file here.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-600}
shift || true
drivers=("$@")
[ ${#drivers[@]} -gt 0 ] || drivers=(fuzz_scene fuzz_msh)
build=${ROCKFDEM_FUZZ_BUILD:-$root/build-fuzz}
jobs=${JOBS:-2}

command -v clang++-14 >/dev/null || {
  echo "fuzz.sh: clang++-14 is missing: apt-get install -y clang-14 libclang-rt-14-dev libomp-14-dev" >&2
  exit 1
}
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
    -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link" \
    -DROCKFDEM_SANITIZE=ON -DROCKFDEM_FUZZ=ON >/dev/null
fi
cmake --build "$build" -j "$jobs" --target "${drivers[@]}"

bash "$root/tests/fuzz/make_corpus.sh" "$build/seeds"

# Leaks inside gmsh's global state are reported at exit by LSan; they are
# not ours (tests/lsan.supp lists them) and must not stop the fuzzer.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/tests/lsan.supp:print_suppressions=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export OMP_NUM_THREADS=1

status=0
for d in "${drivers[@]}"; do
  corpus=$build/corpus/$d
  findings=$build/findings/$d
  mkdir -p "$corpus" "$findings"
  case $d in
    fuzz_scene) seeds=$build/seeds/scene; dict=(-dict="$root/tests/fuzz/scene.dict"); extra=() ;;
    # gmsh 4.8 keeps state across sessions and leaks a FILE (and its file
    # descriptor) each time its MSH 4 reader stops at an error: one process
    # reaches 4 GB after about 5000 inputs. Fork mode restarts the process
    # every few seconds; memory and descriptors start afresh.
    fuzz_checkpoint) seeds=$build/seeds/checkpoint; mkdir -p "$seeds"
      ROCKFDEM_FUZZ_SEED="$seeds/block.ckpt" "$build/bin/$d"; dict=(); extra=() ;;
    fuzz_msh) seeds=$build/seeds/msh; dict=(-dict="$root/tests/fuzz/msh.dict"); extra=(-fork=1 -ignore_ooms=0 ${FUZZ_MSH_EXTRA:-}) ;;
    *) echo "fuzz.sh: unknown driver $d" >&2; exit 1 ;;
  esac
  log=$build/$d.log
  echo "== $d: ${seconds} s, seeds $(ls "$seeds" | wc -l), corpus before $(ls "$corpus" | wc -l)"
  set +e
  # From inside the build folder: fork mode writes fuzz-N.log files to the
  # working directory.
  (cd "$build" && "$build/bin/$d" "$corpus" "$seeds" "${dict[@]}" -max_total_time="$seconds" \
    -timeout=20 -rss_limit_mb=4096 -max_len=65536 -print_final_stats=1 \
    -artifact_prefix="$findings/" "${extra[@]}") >"$log" 2>&1
  rc=$?
  set -e
  # One process: libFuzzer's final stats; fork mode: its last "#N: cov: ..." line.
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' ||
          grep -o '^#[0-9]*: cov' "$log" | tail -1 | tr -dc '0-9' || echo "?")
  echo "   exit $rc, executions $execs, corpus after $(ls "$corpus" | wc -l)," \
       "findings $(ls "$findings" | wc -l) (log: $log)"
  [ $rc -eq 0 ] || status=1
done
echo "command: bash bench/fuzz.sh $seconds ${drivers[*]}  ($(date -u +%Y-%m-%d), $(nproc --all) cores)"
exit $status
