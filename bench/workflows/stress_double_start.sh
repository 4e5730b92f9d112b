#!/usr/bin/env bash
# Simultaneous double starts into one output folder: two `rockfdem run` of
# the same scene started together into the same -o, many times. One run
# per folder means the second is refused (exit 2, naming the holder's PID)
# and never both succeed, which would leave a folder mixing two runs.
#
#   bash bench/workflows/stress_double_start.sh [PAIRS] [BUILD_DIR]
set -uo pipefail
cd "$(dirname "$0")/../.."
pairs=${1:-50}
bin=${2:-build}/bin/rockfdem
scene=tests/workflows/elastic_circular.toml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
both=0 refused=0 by_lock=0
for i in $(seq 1 "$pairs"); do
  "$bin" run "$scene" -q -j 1 -o "$work/out" >"$work/a" 2>&1 &
  a=$!
  "$bin" run "$scene" -q -j 1 -o "$work/out" >"$work/b" 2>&1 &
  b=$!
  wait $a; ra=$?
  wait $b; rb=$?
  if [ $ra -eq 0 ] && [ $rb -eq 0 ]; then both=$((both + 1)); else refused=$((refused + 1)); fi
  grep -q 'in use by another rockfdem run (PID' "$work/a" "$work/b" && by_lock=$((by_lock + 1))
  rm -rf "$work/out"
done
echo "$pairs double starts: both succeeded $both, one refused $refused (by the folder lock: $by_lock)"
