#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# test_cli_run: `rci-cli run` on the example program against the in-process simulator exits 0 and
# writes a finished report, on the real-time clock by default and on the lock-step clock with
# --fast, and says which clock ran; a usage error exits 2; a program refused by the pre-flight
# exits 1 without moving; the KUKA example runs over RSI on the in-process simulated KRC, and a
# program of one family is refused on the other's robot; a demonstrated PATH is replayed on either
# family, its lead-in announced and its deviation reported. Arguments: RCI_CLI EXAMPLE_PROGRAM WORK_DIR.
set -u
cli=$1 example=$2 work=$3
report=$work/cli_run_report.json
rm -f "$report"

fail() { echo "FAIL: $*"; exit 1; }

out=$("$cli" run "$example" --robot sim --speed 0.8 --report "$report" 2>&1) || fail "run of the example exited $?: $out"
test -s "$report" || fail "no report at $report"
grep -q '"outcome": "finished"' "$report" || fail "report outcome is not finished: $(head -c 400 "$report")"
n=$(grep -c '"status": "done"' "$report")
[ "$n" -eq 7 ] || fail "expected 7 instructions done, found $n"
grep -q '"max_tcp_error_m"' "$report" || fail "report has no tracking error"
echo "$out" | grep -q '^finished: 7 instructions in .* (in-process simulator, real-time clock)$' ||
  fail "the default run does not say it ran the real-time clock: $out"

out=$("$cli" run "$example" --robot sim --fast 2>&1) || fail "run --fast of the example exited $?: $out"
echo "$out" | grep -q '^finished: 7 instructions in .* (in-process simulator, lock-step clock, faster than real time; the instructions.* own durations add up to .* s)$' ||
  fail "the --fast run does not say it ran the lock-step clock: $out"
"$cli" run "$example" --robot 127.0.0.1:1 --fast >/dev/null 2>&1
[ $? -eq 2 ] || fail "--fast with a controller address should be a usage error (exit 2)"

"$cli" run "$example" --robot sim --speed 3 >/dev/null 2>&1
[ $? -eq 2 ] || fail "--speed 3 should be a usage error (exit 2)"
"$cli" run --robot sim >/dev/null 2>&1
[ $? -eq 2 ] || fail "a missing program should be a usage error (exit 2)"

# Instruction 2 is 3 m away: refused before anything moves, exit 1, naming the instruction.
bad=$work/cli_unreachable.json
sed 's/0.2251315872475988,/3.0,/' "$example" > "$bad"
grep -q '3.0,' "$bad" || fail "could not build the unreachable program"
out=$("$cli" run "$bad" --robot sim --report "$report" 2>&1)
[ $? -eq 1 ] || fail "an unreachable program should exit 1; output: $out"
echo "$out" | grep -q 'instruction 2 (MOVEL "P2")' || fail "the refusal does not name instruction 2: $out"
grep -q '"outcome": "refused"' "$report" || fail "report of the refused run is not 'refused'"

# A KUKA program over RSI, on the in-process simulated KRC; each family's program refused on the other.
kuka=$(dirname "$example")/kr6_example.json
out=$("$cli" run "$kuka" --robot rsi-sim --report "$report" 2>&1) || fail "run of the KUKA example exited $?: $out"
grep -q '"robot": "kr6_r900_sixx"' "$report" || fail "the KUKA report does not name its robot: $(head -c 300 "$report")"
grep -q '"outcome": "finished"' "$report" || fail "the KUKA run did not finish: $(head -c 400 "$report")"
echo "$out" | grep -q 'over RSI on 127.0.0.1:[0-9]* (in-process simulated KRC), 4 ms cycle, context rci_replay.rsi.xml' ||
  fail "the KUKA run does not say where it ran: $out"
out=$("$cli" run "$kuka" --robot sim 2>&1)
[ $? -eq 1 ] || fail "a KUKA program on the xMate simulator should exit 1: $out"
echo "$out" | grep -q 'a KUKA arm: run it over RSI with --robot rsi:ETHERNET.xml' || fail "no advice for the KUKA program: $out"
out=$("$cli" run "$example" --robot rsi-sim 2>&1)
[ $? -eq 1 ] || fail "an xMate program on the simulated KRC should exit 1: $out"
echo "$out" | grep -q 'an xMate: run it with --robot sim' || fail "no advice for the xMate program: $out"

# The same program against a simulated KRC in another process (rci-sim --rsi, in lock-step), as against a robot:
# rci-cli listens where --bind/--port say and reads the limits from the context given.
data=$(dirname "$(dirname "$example")")
sim=$(dirname "$(dirname "$cli")")/rci-sim/rci-sim
port=$((40000 + $$ % 20000))
out=$("$cli" run "$kuka" --robot "rsi:$data/rsi/RSI_EthernetConfig.xml" --bind 127.0.0.1 --port "$port" 2>&1)
[ $? -eq 1 ] || fail "two contexts naming the config should need --context: $out"
echo "$out" | grep -q 'RSI contexts beside .* name it; give the one the robot runs with --context' ||
  fail "no advice to give --context: $out"
"$sim" --rsi "$data/rsi/rci_replay.rsi.xml" --rsi-target "127.0.0.1:$port" --model kr6_r900_sixx --no-realtime --lockstep \
  > "$work/rci_sim_rsi.log" 2>&1 &
sim_pid=$!
out=$("$cli" run "$kuka" --robot "rsi:$data/rsi/RSI_EthernetConfig.xml" --bind 127.0.0.1 --port "$port" \
  --context "$data/rsi/rci_replay.rsi.xml" 2>&1)
status=$?
kill "$sim_pid" 2>/dev/null
wait "$sim_pid" 2>/dev/null
[ $status -eq 0 ] || fail "run against rci-sim --rsi exited $status: $out; rci-sim: $(cat "$work/rci_sim_rsi.log")"
echo "$out" | grep -q '^finished: 7 instructions' || fail "the run against rci-sim --rsi did not finish: $out"
grep -q 'in lock-step (each cycle as soon as its answer is in), cycle 4 ms' "$work/rci_sim_rsi.log" ||
  fail "rci-sim --rsi --lockstep does not say it runs in lock-step: $(cat "$work/rci_sim_rsi.log")"
# A demonstrated PATH (resources/programs/demonstration.json): the joint move to its start is announced before anything
# moves, the replay line says how long it took, how closely it followed and whether it was slowed; the report has the
# path's fields and the notice.
demo=$(dirname "$example")/demonstration.json
out=$("$cli" run "$demo" --robot sim --fast --report "$report" 2>&1) || fail "run of the PATH example exited $?: $out"
echo "$out" | grep -q '^note: instruction 1 (PATH "wipe"): first moves to the start of the path with a joint move (largest joint change 11.5 deg)$' ||
  fail "the lead-in move is not announced: $out"
echo "$out" | grep -q '^        path 3\.[0-9]* s (demonstrated pace: 3\.000 s; lead-in move 0\.[0-9]* s), deviation from the path 0\.[0-9]* mrad / [0-9.]* mm, never slowed$' ||
  fail "no PATH line within 1 mrad: $out"
grep -q '"outcome": "finished"' "$report" || fail "the PATH run did not finish: $(head -c 400 "$report")"
for field in lead_in_s nominal_duration_s path_joint_deviation_rad path_tcp_deviation_m slowest_pace slowed_share slowest_at_s; do
  grep -q "\"$field\"" "$report" || fail "the PATH report has no $field"
done
grep -q 'first moves to the start of the path' "$report" || fail "the report has no notice of the lead-in"

# A PATH on a KUKA over RSI (the simulated KRC): A1 and A5 out and back in 2 s from the KRC's start pose.
kuka_path=$work/cli_kuka_path.json
awk 'BEGIN {
  pi = atan2(0, -1); d = pi / 180; n = 200
  printf "{\"format\": \"rci-program\", \"version\": 2, \"robot\": \"kr6_r900_sixx\", \"instructions\": [\n"
  printf "{\"type\": \"PATH\", \"name\": \"sweep\", \"rate_hz\": 100, \"speed\": 1, \"q\": [\n"
  for (k = 0; k <= n; ++k) {
    u = k / n; s = u * u * u * (10 - 15 * u + 6 * u * u); f = (1 - cos(2 * pi * s)) / 2
    printf "[%.6f, %.6f, %.6f, %.6f, %.6f, %.6f, 0]%s\n", 10 * f * d, -90 * d, 90 * d, 0, (90 - 8 * f) * d, 0, (k < n ? "," : "")
  }
  printf "]}]}\n"
}' > "$kuka_path"
out=$("$cli" run "$kuka_path" --robot rsi-sim --report "$report" 2>&1) || fail "run of the KUKA PATH exited $?: $out"
echo "$out" | grep -q '^        path 2\.[0-9]* s (demonstrated pace: 2\.000 s), deviation from the path 0\.[0-9]* mrad' ||
  fail "no KUKA PATH line within 1 mrad: $out"
grep -q '"outcome": "finished"' "$report" || fail "the KUKA PATH run did not finish: $(head -c 400 "$report")"
echo "13 passed, 0 failed"
