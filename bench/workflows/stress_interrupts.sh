#!/usr/bin/env bash
# Randomised interrupt/restart cycles: SIGTERM at a random moment of a
# tunnel run with lining, bolts, grouting and fracture (grout stage long
# enough to be hit: trigger 400 broken), restart from the checkpoint the
# signal wrote, with a random thread count each side; every restart must
# end on the uninterrupted run's state hash.
#
#   bash bench/workflows/stress_interrupts.sh [CYCLES] [BUILD_DIR]
#
# Prints how many restarts matched, by the stage the signal hit. Signals
# that land before the explicit stages leave no checkpoint and are counted
# apart.
set -uo pipefail
cd "$(dirname "$0")/../.."
cycles=${1:-30}
bin=${2:-build}/bin/rockfdem
scene=(tests/workflows/restart_support.toml --set 'stages[4].trigger_broken=400' --set output.vtk=false -q)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$bin" run "${scene[@]}" -j 1 -o "$work/ref" >/dev/null 2>&1
hash() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['state_hash'])" "$1"; }
ref=$(hash "$work/ref/summary.json")
same=0 diff=0 none=0
declare -A by_stage
RANDOM=7
for i in $(seq 1 "$cycles"); do
  delay=$(python3 -c "import random; random.seed($i); print(round(random.uniform(0.85, 1.45), 3))")
  j1=$((1 + RANDOM % 2)) j2=$((1 + RANDOM % 2))
  rm -rf "$work/run"
  timeout --preserve-status -s TERM "$delay" "$bin" run "${scene[@]}" -j "$j1" -o "$work/run" >"$work/log" 2>&1
  checkpoint=$(ls "$work"/run/checkpoints/*.rfck 2>/dev/null | tail -1)
  stage=$(grep -o "in stage '[a-z_]*'" "$work/log" | cut -d"'" -f2)
  if [ -z "$checkpoint" ]; then none=$((none + 1)); continue; fi
  "$bin" run "${scene[@]}" -j "$j2" --restart "$checkpoint" -o "$work/run" >/dev/null 2>&1
  by_stage[$stage]=$((${by_stage[$stage]:-0} + 1))
  if [ "$(hash "$work/run/summary.json")" = "$ref" ]; then
    same=$((same + 1))
  else
    diff=$((diff + 1))
    echo "different: delay $delay s, -j $j1 then -j $j2, stage $stage, $(basename "$checkpoint")"
  fi
done
echo "reference $ref; $cycles cycles: same hash $same, different $diff, signal before the explicit stages $none"
for s in "${!by_stage[@]}"; do echo "  restarts from stage $s: ${by_stage[$s]}"; done
