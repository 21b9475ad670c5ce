#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The packaging test (ctest test_package): the distribution's validators accept the desktop file,
# the AppStream metadata and the Debian package (lintian: no errors; the warnings we keep are listed
# in docs/packaging.md), and the programs start from an unpacked .deb and from `cmake --install`
# into a fresh prefix -- so a file missing from the package or a library they cannot find is caught.
# Usage: check_package.sh BUILD_DIR SOURCE_DIR
set -eu
build=$1
source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

step() { printf '\n== %s\n' "$*"; }

step "desktop-file-validate"
desktop-file-validate "$source/packaging/rci-studio.desktop"

step "appstreamcli validate"
appstreamcli validate --no-net "$source/packaging/rci-studio.metainfo.xml"

step "cpack -G DEB"
(cd "$build" && cpack -G DEB -B "$work/deb" >"$work/cpack.log" 2>&1) || { cat "$work/cpack.log"; exit 1; }
deb=$(ls "$work"/deb/*.deb)
echo "$deb"

step "lintian (errors fail the test)"
lintian --fail-on error --tag-display-limit 0 "$deb"

# Runs the three programs of a tree rooted at $1 (its bin/ and share/), with no build tree or
# source tree to fall back on for the library: only the tree's own RUNPATH.
run_programs() {
  root=$1
  env -u LD_LIBRARY_PATH "$root/bin/rci-cli" --version
  env -u LD_LIBRARY_PATH "$root/bin/rci-sim" --help >/dev/null
  env -u LD_LIBRARY_PATH "$root/bin/rci-sim" --version
  env -u LD_LIBRARY_PATH QT_QPA_PLATFORM=offscreen "$root/bin/rci-studio" --version
  env -u LD_LIBRARY_PATH RCI_DATA_DIR="$root/share/rci" "$root/bin/rci-cli" model >/dev/null
  for f in share/rci/resources/robots/xmate7_pro.urdf share/applications/rci-studio.desktop \
           share/metainfo/rci-studio.metainfo.xml share/man/man1/rci-cli.1.gz share/man/man1/rci-sim.1.gz \
           share/man/man1/rci-studio.1.gz share/doc/rci-studio/copyright share/doc/rci-studio/changelog.gz \
           include/xmate/robot.h; do
    [ -f "$root/$f" ] || { echo "missing from the installed tree: $f" >&2; exit 1; }
  done
  # The client library carries no simulator: the simulators are librci-sim, linked into the programs.
  lib=$(find "$root" -name 'librci-core.so.*.*' | head -n 1)
  [ -n "$lib" ] || { echo "librci-core.so is missing from the installed tree" >&2; exit 1; }
  if nm -DC --defined-only "$lib" | grep -q 'xmate::sim::'; then
    echo "$lib exports the simulator (xmate::sim::); it belongs in librci-sim" >&2
    exit 1
  fi
}

step "the unpacked .deb"
dpkg-deb -x "$deb" "$work/unpacked"
run_programs "$work/unpacked/usr"

step "cmake --install into a fresh prefix"
cmake --install "$build" --prefix "$work/prefix" >/dev/null
run_programs "$work/prefix"

step "package checks passed"
