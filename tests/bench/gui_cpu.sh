#!/bin/bash
# SPDX-License-Identifier: Apache-2.0
# Measures the CPU share of one core of rci-studio streaming from its built-in simulator (idle arm,
# 30 Hz plots and status, 3D view), under xvfb (3D rendered with Mesa) and offscreen (no 3D), and as
# a reference in the same run the simulator + client alone (rci-sim streaming to `rci-cli state`).
# usage: tests/bench/gui_cpu.sh BUILD_DIR [SECONDS]   (results: docs/performance.md, "The window")
set -eu
build=$(cd "$1" && pwd); seconds=${2:-10}
export RCI_DATA_DIR=${RCI_DATA_DIR:-$(cd "$(dirname "$0")/../.." && pwd)}
export LIBGL_ALWAYS_SOFTWARE=1 QT3D_RENDERER=opengl XDG_CONFIG_HOME=$(mktemp -d)

# cpu_share PID: percent of one core used by PID over $seconds, after a 5 s warm-up.
cpu_share() {
  sleep 5
  local tck a b c d t0 t1
  tck=$(getconf CLK_TCK)
  read -r a b < <(awk '{print $14, $15}' "/proc/$1/stat"); t0=$(date +%s%N)
  sleep "$seconds"
  read -r c d < <(awk '{print $14, $15}' "/proc/$1/stat"); t1=$(date +%s%N)
  awk -v u=$((c + d - a - b)) -v t=$((t1 - t0)) -v k="$tck" 'BEGIN { printf "%.1f", 100 * u / k / (t / 1e9) }'
}

if [ -z "${RCI_GUI_CPU_INNER:-}" ]; then
  # Under xvfb: the whole window with the 3D view.
  RCI_GUI_CPU_INNER=xvfb xvfb-run -a -s "-screen 0 1600x1000x24" "$0" "$build" "$seconds"
  RCI_GUI_CPU_INNER=offscreen QT_QPA_PLATFORM=offscreen "$0" "$build" "$seconds"
  # Reference: the simulator and a client reading states, without any window.
  "$build/app/rci-sim/rci-sim" --port 0 --print-port --no-realtime > /tmp/gui_cpu_sim.$$ 2>/dev/null &
  sim=$!
  for _ in $(seq 50); do port=$(head -n1 /tmp/gui_cpu_sim.$$ 2>/dev/null || true); [ -n "$port" ] && break; sleep 0.1; done
  "$build/app/rci-cli/rci-cli" state --robot "127.0.0.1:$port" > /dev/null &
  cli=$!
  sim_share=$(cpu_share $sim)
  cli_share=$(cpu_share $cli)
  echo "reference (no window): rci-sim $sim_share % + rci-cli state $cli_share % of one core"
  kill $cli $sim 2>/dev/null; wait 2>/dev/null; rm -f /tmp/gui_cpu_sim.$$
  exit 0
fi
"$build/app/rci-studio/rci-studio" > /dev/null 2>&1 &
pid=$!
echo "rci-studio ($RCI_GUI_CPU_INNER): $(cpu_share $pid) % of one core"
kill $pid; wait $pid 2>/dev/null || true
