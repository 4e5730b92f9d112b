#!/usr/bin/env bash
# Randomised interrupt/restart cycles: SIGTERM at a random moment of a run,
# restart from the checkpoint the signal wrote, with a random thread count
# each side; every restart must end on the uninterrupted run's state hash
# (and, for a specimen, its history.csv).
#
#   bash bench/workflows/stress_interrupts.sh [CYCLES] [BUILD_DIR] [tunnel|specimen]
#
# tunnel (the default): lining, bolts, grouting and fracture (grout stage
# long enough to be hit: trigger 400 broken); counts by the stage the
# signal hit. specimen: the small UCS loaded past its peak (6000 steps, a
# row every 250); counts by whether the signal landed on an output step or
# between two. Signals that land before the explicit steps leave no
# checkpoint and are counted apart, as are runs that ended first.
set -uo pipefail
cd "$(dirname "$0")/../.."
cycles=${1:-30}
bin=${2:-build}/bin/rockfdem
kind=${3:-tunnel}
case $kind in
  tunnel)
    scene=(tests/workflows/restart_support.toml --set 'stages[4].trigger_broken=400' --set output.vtk=false -q)
    earliest=0.85 latest=1.45 ;;
  specimen)
    scene=(tests/workflows/ucs_small.toml --set engine.steps=6000 --set output.every_steps=250 --set output.vtk=false -q)
    earliest=1.8 latest=3.4 ;;
  *) echo "unknown kind '$kind': tunnel or specimen" >&2; exit 2 ;;
esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$bin" run "${scene[@]}" -j 1 -o "$work/ref" >/dev/null 2>&1
hash() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['state_hash'])" "$1"; }
ref=$(hash "$work/ref/summary.json")
same=0 diff=0 none=0 finished=0
declare -A by_where
RANDOM=7
for i in $(seq 1 "$cycles"); do
  delay=$(python3 -c "import random; random.seed($i); print(round(random.uniform($earliest, $latest), 3))")
  j1=$((1 + RANDOM % 2)) j2=$((1 + RANDOM % 2))
  rm -rf "$work/run"
  timeout --preserve-status -s TERM "$delay" "$bin" run "${scene[@]}" -j "$j1" -o "$work/run" >"$work/log" 2>&1
  code=$?
  checkpoint=$(ls "$work"/run/checkpoints/*.rfck 2>/dev/null | tail -1)
  if [ "$code" = 0 ]; then finished=$((finished + 1)); continue; fi
  if [ -z "$checkpoint" ]; then none=$((none + 1)); continue; fi
  if [ "$kind" = tunnel ]; then
    where=$(grep -o "in stage '[a-z_]*'" "$work/log" | cut -d"'" -f2)
  else
    step=$(basename "$checkpoint" .rfck | sed 's/checkpoint_0*//')
    [ $((${step:-0} % 250)) = 0 ] && where="an output step" || where="between output steps"
  fi
  "$bin" run "${scene[@]}" -j "$j2" --restart "$checkpoint" -o "$work/run" >/dev/null 2>&1
  by_where[$where]=$((${by_where[$where]:-0} + 1))
  if [ "$(hash "$work/run/summary.json")" = "$ref" ] &&
    { [ "$kind" = tunnel ] || cmp -s "$work/run/history.csv" "$work/ref/history.csv"; }; then
    same=$((same + 1))
  else
    diff=$((diff + 1))
    echo "different: delay $delay s, -j $j1 then -j $j2, $where, $(basename "$checkpoint")"
  fi
done
echo "$kind: reference $ref; $cycles cycles: same result $same, different $diff," \
  "signal before the explicit steps $none, run ended before the signal $finished"
for w in "${!by_where[@]}"; do echo "  restarts from $w: ${by_where[$w]}"; done
