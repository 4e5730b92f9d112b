#!/usr/bin/env bash
# The two set-up commands of the README:
#   bash scripts/setup.sh run    install what is missing, build (Release), run the default tunnel
#   bash scripts/setup.sh test   install what is missing, build (Release), run the whole test suite
set -euo pipefail
cd "$(dirname "$0")/.."

mode=${1:-}
case "$mode" in run|test) ;; *) echo "usage: bash scripts/setup.sh run|test" >&2; exit 2 ;; esac

bash scripts/install-deps.sh
build=${ROCKFDEM_BUILD_DIR:-build}
# ROCKFDEM_WERROR=ON makes warnings errors (CI sets it: .ci/run); unset, the
# build folder keeps what it was configured with (OFF in a new one).
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  ${ROCKFDEM_WERROR:+-DROCKFDEM_WERROR="$ROCKFDEM_WERROR"} >/dev/null
cmake --build "$build" -j "$(nproc)"

if [ "$mode" = run ]; then
  # PNG plots need a display; Xvfb stands in for one on a headless machine.
  xvfb=()
  [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null && xvfb=(xvfb-run -a)
  "${xvfb[@]}" "$build/bin/rockfdem" run -o out/default --force
else
  ctest --test-dir "$build" --output-on-failure -j "$(nproc)"
fi
