#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer,
# run before each release (docs/reliability.md: why not in .ci/run, timings,
# what was found).
#
#   bash tests/sanitize.sh            # configure, build (-j2), ctest
#   JOBS=4 bash tests/sanitize.sh     # more build jobs where there are cores
#
# Build: build-asan/ (RelWithDebInfo, -DROCKFDEM_SANITIZE=ON, GCC). Any
# sanitizer report fails the test that made it (halt_on_error, exitcode 1).
# Leak reports from system libraries (OpenMPI, gmsh, TBB, VTK, Trilinos)
# are suppressed by tests/lsan.supp; nothing of ours is.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${ROCKFDEM_ASAN_BUILD:-$root/build-asan}
jobs=${JOBS:-2}

# Also during the build: gtest_discover_tests runs each test binary.
# fast_unwind_on_malloc=0: OpenMPI, Trilinos and gmsh are built without frame
# pointers, so the fast unwinder stops at "<unknown module>" and their leak
# reports could not be matched by tests/lsan.supp.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:fast_unwind_on_malloc=0:halt_on_error=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/tests/lsan.supp:print_suppressions=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-2}

start=$(date +%s)
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DROCKFDEM_SANITIZE=ON >/dev/null
cmake --build "$build" -j "$jobs"
built=$(date +%s)
set +e
ctest --test-dir "$build" --output-on-failure -j "$jobs" --timeout 1500 | tee "$build/ctest.log"
rc=${PIPESTATUS[0]}
set -e
done_at=$(date +%s)
echo "sanitize.sh: build $((built - start)) s, tests $((done_at - built)) s, ctest exit $rc" \
     "($(date -u +%Y-%m-%d), $(nproc --all) cores)"
exit "$rc"
