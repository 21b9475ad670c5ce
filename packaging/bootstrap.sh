#!/bin/sh
# The README's two commands:
#   packaging/bootstrap.sh run    install what is missing, build, start RCI Studio on the built-in simulator
#   packaging/bootstrap.sh test   install what is missing, build, run every test
# Build trees: build/ (RelWithDebInfo); the test command also uses build-asan/ (sanitizers).
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
    exec build/app/rci-cli/rci-cli
    ;;
  test)
    configure build -DCMAKE_BUILD_TYPE=RelWithDebInfo
    cmake --build build -j "$jobs"
    (cd build && ctest --output-on-failure -j "$jobs")
    ;;
  *)
    echo "usage: packaging/bootstrap.sh run|test" >&2
    exit 2
    ;;
esac
