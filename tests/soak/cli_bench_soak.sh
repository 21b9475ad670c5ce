#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# test_cli_bench_soak: `rci-cli bench soak` refuses bad values with exit 2, and a short control run
# (lock-step clock, nothing lost, no burners) exits 0 with its table and its JSON. Arguments: RCI_CLI.
set -u
cli=$1

fail() { echo "FAIL: $*"; exit 1; }

# run CODE ARGS...: rci-cli bench soak ARGS exits CODE; its stdout + stderr are in $out.
run() {
  local code=$1
  shift
  out=$("$cli" bench soak "$@" 2>&1)
  local status=$?
  [ "$status" -eq "$code" ] || fail "rci-cli bench soak $* exited $status, expected $code: $out"
}

# says TEXT: the last run's output contains TEXT.
says() {
  case "$out" in
    *"$1"*) ;;
    *) fail "the output does not say '$1': $out" ;;
  esac
}

run 2 --loss 70
says "--loss takes a percentage from 0 to 50, got '70'"
run 2 --motions 0
says "--motions takes a whole number from 1 to 1000000, got '0'"
run 2 --seed x
says "--seed takes a whole number from 0 to 2147483647, got 'x'"
run 0 --help
says "--no-burners"

run 0 --motions 3 --loss 0 --no-burners --lockstep
for text in "motion" "MOVEJ" "MOVEL" "joint callback" "recovery moves" "all motions" "the client counted"; do
  says "$text"
done
run 0 --motions 2 --loss 0 --no-burners --lockstep --json
for text in '"failures": 0' '"motions": 2' '"MOVEJ": {' '"states_missed"' '"loss_bursts": 0' '"clock": "lockstep"'; do
  says "$text"
done
echo "test_cli_bench_soak: passed"
