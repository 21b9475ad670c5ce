#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The README's two commands:
#   packaging/bootstrap.sh run    install what is missing, build, start RCI Studio (rci-studio) on the built-in simulator
#   packaging/bootstrap.sh test   install what is missing, build, run every test
# Build trees: build/ (RelWithDebInfo); the test command also uses build-asan/ (ASan + UBSan),
# build-tsan/ (clang, ThreadSanitizer) and build-fuzz/ (clang, libFuzzer).
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
mode=${1:-run}
jobs=$(nproc 2>/dev/null || echo 2)

"$here/packaging/deps.sh"

configure() {  # configure <dir> [cmake args...]
  dir=$1; shift
  [ -f "$dir/CMakeCache.txt" ] || cmake -S . -B "$dir" -G Ninja "$@"
}

case "$mode" in
  run)
    configure build -DCMAKE_BUILD_TYPE=RelWithDebInfo
    cmake --build build -j "$jobs"
    exec build/app/rci-studio/rci-studio
    ;;
  test)
    configure build -DCMAKE_BUILD_TYPE=RelWithDebInfo
    cmake --build build -j "$jobs"
    (cd build && ctest --output-on-failure -j "$jobs")
    # The core and its tests again under AddressSanitizer + UBSan: no GUI, no benchmarks; -O1 with
    # line tables keeps the build short. Tests labelled no_asan cannot run under ASan. Real-time
    # scheduling is off: SCHED_FIFO threads slowed down by ASan could starve the parallel tests.
    configure build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" \
      -DRCI_SANITIZE=ON -DRCI_BUILD_GUI=OFF -DRCI_BUILD_BENCH=OFF
    cmake --build build-asan -j "$jobs"
    # tests/lsan.supp: Qt's own allocations only (QtTest's watchdog thread at exit).
    (cd build-asan && RCI_NO_REALTIME=1 LSAN_OPTIONS="suppressions=$here/tests/lsan.supp print_suppressions=0" \
      ctest --output-on-failure -j "$jobs" -LE no_asan)
    # The client under ThreadSanitizer (clang: GCC 12 leaves large struct copies uninstrumented and
    # misses races on RobotState): only the tests labelled tsan, built alone. io_sync=0: by default
    # every socket call counts as synchronisation, which hides races between threads that talk over
    # loopback. The suppressions cover Qt's uninstrumented internals only. Real-time scheduling off.
    configure build-tsan -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" -DRCI_TSAN=ON -DRCI_BUILD_GUI=OFF -DRCI_BUILD_BENCH=OFF
    cmake --build build-tsan -j "$jobs" --target test_threads test_robot_commands test_faults test_moves \
      test_joint_stream test_executor_rsi test_arm test_admittance
    (cd build-tsan && RCI_NO_REALTIME=1 \
      TSAN_OPTIONS="io_sync=0 halt_on_error=1 second_deadlock_stack=1 suppressions=$here/tests/tsan.supp" \
      ctest --output-on-failure -j "$jobs" -L tsan)
    # libFuzzer (clang): every decoder for a bounded time from a seed corpus made in the build.
    configure build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
      "-DCMAKE_CXX_FLAGS=-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined" \
      "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" \
      -DRCI_BUILD_FUZZERS=ON -DRCI_BUILD_TESTS=OFF -DRCI_BUILD_GUI=OFF -DRCI_BUILD_BENCH=OFF
    RCI_NO_REALTIME=1 cmake --build build-fuzz -j "$jobs" --target fuzz_run
    ;;
  *)
    echo "usage: packaging/bootstrap.sh run|test" >&2
    exit 2
    ;;
esac
