#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# test_guide_cli: `rci-cli guide` hand-guides a KUKA as against a real cell -- rci-sim --rsi (the
# simulated KRC, in lock-step) with its simulated F/T sensor and control port in another process.
# Pushed 30 N along +x through the control port, the flange moves along +x; at --seconds the guide
# brakes to rest and ends "stopped by the operator" with exit 0; a guide without its sensor says
# what to check and exits 1; an xMate model is refused (exit 2). Arguments: RCI_CLI RCI_SIM DATA_DIR.
set -u
cli=$1 sim=$2 data=$3
fail() { echo "FAIL: $*"; exit 1; }
base=$((20000 + ($$ % 2000) * 10))
rsi_port=$base ft_port=$((base + 1)) control_port=$((base + 2))
config=$data/resources/rsi/RSI_EthernetConfig.xml context=$data/resources/rsi/rci_replay.rsi.xml
log=$(mktemp)
out_file=$(mktemp)
trap 'kill $sim_pid 2>/dev/null; rm -f "$log" "$out_file"' EXIT

"$sim" --rsi "$context" --rsi-target "127.0.0.1:$rsi_port" --model kr6_r900_sixx --no-realtime --lockstep \
  --ft-sensor "$ft_port" --control-port "$control_port" >"$log" 2>&1 &
sim_pid=$!

"$cli" guide --robot "rsi:$config" --context "$context" --bind 127.0.0.1 --port "$rsi_port" --model kr6_r900_sixx \
  --sensor "127.0.0.1:$ft_port" --seconds 4 >"$out_file" 2>&1 &
guide_pid=$!
# Once it guides (its header is out), push along +x through the simulator's control port.
for _ in $(seq 1 100); do grep -q '^# t\[s\]' "$out_file" && break; sleep 0.1; done
grep -q '^# t\[s\]' "$out_file" || fail "rci-cli guide did not start guiding: $(cat "$out_file"); rci-sim: $(cat "$log")"
sleep 0.5
exec 3<>"/dev/tcp/127.0.0.1/$control_port" || fail "no control port on $control_port: $(cat "$log")"
echo "wrench 30 0 0 0 0 0" >&3
read -r answer <&3
exec 3>&-
case $answer in ok*) ;; *) fail "the control port answered '$answer'" ;; esac
wait $guide_pid
status=$?
out=$(cat "$out_file")
[ $status -eq 0 ] || fail "rci-cli guide exited $status: $out"
echo "$out" | grep -q '^guiding ended: stopped by the operator$' || fail "no end line: $out"
first_x=$(echo "$out" | awk '/^ *[0-9]+\.[0-9]+ /{print $2; exit}')
last_x=$(echo "$out" | awk '/^ *[0-9]+\.[0-9]+ /{x=$2} END{print x}')
awk -v a="$first_x" -v b="$last_x" 'BEGIN{exit !(b - a > 20)}' || fail "the flange did not move along +x ($first_x -> $last_x mm): $out"

# Without the sensor: says what to check, exits 1.
"$cli" guide --robot "rsi:$config" --context "$context" --bind 127.0.0.1 --port "$rsi_port" --model kr6_r900_sixx \
  --sensor "127.0.0.1:$((base + 3))" --seconds 1 >"$out_file" 2>&1
status=$?
[ $status -eq 1 ] || fail "a guide without its sensor should exit 1, got $status: $(cat "$out_file")"
grep -q 'no data from the F/T sensor at 127.0.0.1:[0-9]* within 2 s; check its address' "$out_file" ||
  fail "no advice about the sensor: $(cat "$out_file")"

# An xMate guides itself.
"$cli" guide --robot "rsi:$config" --model xmate7_pro --sensor 127.0.0.1 >"$out_file" 2>&1
[ $? -eq 2 ] || fail "an xMate model should be a usage error: $(cat "$out_file")"
grep -q "guide drives a KUKA arm over RSI" "$out_file" || fail "no reason for refusing the xMate: $(cat "$out_file")"
echo "3 passed, 0 failed"
