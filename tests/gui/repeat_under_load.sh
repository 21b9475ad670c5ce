#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Runs one test executable N times in a row while two CPU-burning processes load the machine, and
# stops at the first failure. For the GUI scenarios that must hold on a busy lab PC, e.g.:
#   tests/gui/repeat_under_load.sh 20 build/tests/gui/test_operator_scenario
#   tests/gui/repeat_under_load.sh 20 xvfb-run -a -s "-screen 0 1600x1000x24" build/tests/gui/test_operator_scenario
# Prints "N passed, 0 failed" when every run passed; exit status 1 at the first failure.
set -u
[ $# -ge 2 ] || { echo "usage: $0 COUNT COMMAND [ARGS...]" >&2; exit 2; }
count=$1; shift
export QT_QPA_PLATFORM=${QT_QPA_PLATFORM:-offscreen}
burners=""
for i in 1 2; do
  timeout 3600 sh -c 'while :; do :; done' &
  burners="$burners $!"
done
trap 'kill $burners 2>/dev/null' EXIT INT TERM
passed=0
while [ "$passed" -lt "$count" ]; do
  log=$(mktemp)
  if "$@" >"$log" 2>&1; then
    passed=$((passed + 1))
    echo "run $passed: passed"
    rm -f "$log"
  else
    echo "run $((passed + 1)): FAILED; its output:" >&2
    cat "$log" >&2
    rm -f "$log"
    echo "$passed passed, 1 failed"
    exit 1
  fi
done
echo "$passed passed, 0 failed"
