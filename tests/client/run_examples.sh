#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The examples test: installs the built project into a temporary prefix, builds examples/ against
# it like a user's project (find_package(RCI)), and runs each example to completion (exit 0)
# against the installed rci-sim on a free port with the lock-step clock.
# usage: run_examples.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1
source=$2
work=$(mktemp -d)
sim_pid=""

cleanup() {
  if [[ -n "$sim_pid" ]]; then kill "$sim_pid" 2>/dev/null || true; wait "$sim_pid" 2>/dev/null || true; fi
  rm -rf "$work"
}
trap cleanup EXIT

step() { echo "== $*"; }

step "install into $work/prefix"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
step "configure and build examples/ against the installed package"
cmake -S "$source/examples" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log" ||
  { cat "$work/configure.log"; exit 1; }
cmake --build "$work/build" -j 2 > "$work/build.log" || { cat "$work/build.log"; exit 1; }

# Installed programs carry no RPATH: point them at the installed library and data.
libdir=$(dirname "$(find "$work/prefix" -name 'librci-core.so*' -print -quit)")
export LD_LIBRARY_PATH="$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export RCI_DATA_DIR="$work/prefix/share/rci"

# Starts the installed rci-sim for model $1 on a free port; sets sim_pid and port.
# Each start writes a fresh file: the redirection happens in the background child, so reading a
# reused file could return the previous simulator's port.
start_sim() {
  sim_starts=$((${sim_starts:-0} + 1)); sim_out="$work/sim-$sim_starts.out"
  "$work/prefix/bin/rci-sim" --model "$1" --lockstep --port 0 --print-port > "$sim_out" 2> "$work/sim.err" &
  sim_pid=$!
  for _ in $(seq 1 100); do
    port=$(head -n 1 "$sim_out" 2>/dev/null || true)
    if [[ "$port" =~ ^[0-9]+$ ]]; then return 0; fi
    sleep 0.1
  done
  echo "rci-sim did not print its port:"; cat "$sim_out" "$work/sim.err"; exit 1
}

stop_sim() {
  kill "$sim_pid"; wait "$sim_pid" 2>/dev/null || true; sim_pid=""
}

step "joint_motion (manual 2.3.3)"
start_sim xmate7_pro
timeout 120 "$work/build/joint_motion" "127.0.0.1:$port"
stop_sim

step "cartesian_motion (manual 2.5.1)"
start_sim xmate7_pro
timeout 180 "$work/build/cartesian_motion" "127.0.0.1:$port"
stop_sim

step "ini_joint_motion (manual 2.5.2)"
start_sim xmate7
printf '; written by run_examples.sh\n[network]\nip = 127.0.0.1\nport = %s\n' "$port" > "$work/xmate.ini"
(cd "$work" && timeout 120 "$work/build/ini_joint_motion")
stop_sim

step "all examples ran to completion"
