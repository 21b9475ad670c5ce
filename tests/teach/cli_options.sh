#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# test_cli_options: rci-cli's command line (CLI11). Bad values, unknown options, missing values and
# options that exclude each other exit 2 and say what was wrong, followed by the command's usage;
# every command has its own --help (exit 0). Nothing here connects to a robot.
# Arguments: RCI_CLI.
set -u
cli=$1
passed=0

fail() { echo "FAIL: $*"; exit 1; }

# expect CODE TEXT ARGS...: rci-cli ARGS exits CODE and its output (stdout + stderr) contains TEXT.
expect() {
  local code=$1 text=$2
  shift 2
  local out status
  out=$("$cli" "$@" 2>&1)
  status=$?
  [ "$status" -eq "$code" ] || fail "rci-cli $* exited $status, expected $code: $out"
  case "$out" in
    *"$text"*) ;;
    *) fail "rci-cli $* does not say '$text': $out" ;;
  esac
  passed=$((passed + 1))
}

# Values out of range, for each typed option.
expect 2 "--cycles takes a whole number from 1500 to 10000000, got '5'" bench loop --cycles 5
expect 2 "--cycles takes a whole number from 1000 to 100000000, got 'many'" bench client --cycles=many
expect 2 "--count takes a whole number from 1 to 100000000, got '0'" state --robot 127.0.0.1:1 --count 0
expect 2 "--speed takes a speed override from 0.1 to 1.0 (e.g. 0.5 = 50 %), got '3'" run p.json --robot sim --speed 3
expect 2 "--robot '10.0.0.1:99999': the port must be a whole number from 1 to 65535, got '99999'" \
  state --robot 10.0.0.1:99999
expect 2 "--robot ':1337': no host; write sim (the in-process simulator) or HOST:PORT" run p.json --robot :1337
expect 2 "--robot 'sim': this command needs a controller address; write HOST:PORT" state --robot sim
expect 2 "--model: unknown model 'ur5'; choose one of: xmate3_pro, xmate7_pro, xmate3, xmate7" \
  bench loop --model ur5
expect 2 "NAME: unknown model 'xmate9'" model xmate9
# Unknown options and commands, extra arguments.
expect 2 "state: unknown option '--frobnicate'" state --robot 127.0.0.1:1 --frobnicate
expect 2 "unknown command 'frob' (known: model, state, run, guide, doctor, bench, ft, help)" frob
expect 2 "unknown bench 'fast' (known: loop, client, rsi, path, soak)" bench fast
expect 2 "model: unexpected argument 'xmate3'" model xmate7 xmate3
# Missing values and missing required arguments.
expect 2 "--robot needs a value" state --robot
expect 2 "--cycles needs a value" bench loop --cycles
expect 2 "state needs --robot HOST:PORT (an xMate) or --robot rsi:ETHERNET.xml (a KUKA over RSI)" state --count 3
expect 2 "run needs --robot sim or --robot HOST:PORT" run p.json
expect 2 "run needs a program file (PROGRAM.json)" run --robot sim
expect 2 "bench needs 'loop', 'client', 'rsi', 'path' or 'soak'" bench
# Options that exclude each other.
expect 2 "--fast applies to the in-process simulator (--robot sim)" run p.json --robot 127.0.0.1:1 --fast
# run on a KUKA over RSI: the RSI options only with rsi:, a cycle of 4 or 12 ms.
expect 2 "--bind, --port, --context and --cycle-ms apply to a KUKA over RSI" run p.json --robot sim --context c.rsi.xml
expect 2 "--cycle-ms" run p.json --robot rsi-sim --cycle-ms 5
expect 2 "--robot 'rsi-sim': this command needs a robot" state --robot rsi-sim
expect 2 "--robot 'rsi:': no file; write rsi:ETHERNET.xml" run p.json --robot rsi:
expect 2 "--lockstep applies to the in-process simulator (--robot sim)" bench loop --robot 127.0.0.1:1 --lockstep
# A usage error is followed by the usage of the command it is about.
expect 2 "Usage: rci-cli bench loop [OPTIONS]" bench loop --cycles 5
# Help: the whole program and each command.
expect 0 "run a taught program" --help
expect 0 "bench" help
expect 0 "--report FILE" run --help
expect 0 "--lockstep" bench loop --help
expect 0 "--count N" state -h
expect 0 "rci-cli 0." --version
# ft: the sensor's address and its checks; a sensor that does not answer is a run-time failure.
expect 2 "--sensor '192.168.1.1:0': the port must be a whole number from 1 to 65535" ft --sensor 192.168.1.1:0
expect 2 "--sensor is required" ft
expect 2 "--count takes a whole number from 1 to 100000000, got '0'" ft --sensor 127.0.0.1 --count 0
expect 0 "--counts-per-unit C" ft --help
expect 1 "no data from the F/T sensor at 127.0.0.1:9 within 2 s" ft --sensor 127.0.0.1:9 --count 1
# state over RSI (--robot rsi:FILE): a KUKA model is required, and the RSI options only go with it.
expect 2 "--robot rsi:... needs --model NAME, the KUKA arm: kr6_r900_sixx, kr16_2" state --robot rsi:x.xml
expect 2 "--model 'xmate7_pro' is not a KUKA model; with --robot rsi:... choose one of: kr6_r900_sixx, kr16_2" \
  state --robot rsi:x.xml --model xmate7_pro
expect 2 "--model 'kr16_2' is a KUKA arm, which speaks RSI: write --robot rsi:ETHERNET.xml" \
  state --robot 127.0.0.1:1 --model kr16_2
expect 2 "--model: unknown model 'ur5'; choose one of: xmate3_pro, xmate7_pro, xmate3, xmate7 (xMate, --robot HOST:PORT) or kr6_r900_sixx, kr16_2 (KUKA, --robot rsi:ETHERNET.xml)" \
  state --robot rsi:x.xml --model ur5
expect 2 "--bind applies to a KUKA over RSI (--robot rsi:ETHERNET.xml)" state --robot 127.0.0.1:1 --bind 127.0.0.1
expect 2 "--port applies to a KUKA over RSI (--robot rsi:ETHERNET.xml)" state --robot 127.0.0.1:1 --port 5
expect 2 "--robot 'rsi:': no file; write rsi:ETHERNET.xml" state --robot rsi: --model kr16_2
expect 2 "--bind takes an IPv4 address of this PC (e.g. 192.168.1.20, or 0.0.0.0 for every address), got 'pc'" \
  state --robot rsi:x.xml --model kr16_2 --bind pc
expect 2 "--port takes a whole number from 0 to 65535, got '70000'" state --robot rsi:x.xml --model kr16_2 --port 70000
expect 2 "--cycles takes a whole number from 100 to 100000000, got '5'" bench rsi --cycles 5
expect 1 "x.xml: cannot open" state --robot rsi:x.xml --model kr16_2
expect 0 "--wait S" state --help
expect 0 "tinyxml2" bench rsi --help
expect 2 "--seconds takes a whole number from 1 to 3600, got '0'" bench path --seconds 0
# bench path runs offline: a short recording reduced to 100 Hz within the bound, and re-timed.
expect 0 "stored at 100 Hz" bench path --seconds 3 --rounds 1
# guide: a KUKA over RSI only; its decimal options in range.
expect 2 "--robot: guide takes rsi:ETHERNET.xml, the KUKA's Ethernet config" guide --robot 127.0.0.1:1 --model kr16_2 --sensor 127.0.0.1
expect 2 "--max-speed takes a speed from 0.01 to 1.0 m/s, got '5'" guide --robot rsi:x.xml --model kr16_2 --sensor 127.0.0.1 --max-speed 5
expect 2 "--axes" guide --robot rsi:x.xml --model kr16_2 --sensor 127.0.0.1 --axes sideways

# The default and a model, with --opt=value and --opt value (no robot needed).
expect 0 "xMate Pro 7 (xmate7_pro), 7 axes"
expect 0 "xMate 3 (xmate3), 6 axes" model xmate3

echo "$passed passed, 0 failed"
