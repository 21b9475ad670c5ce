#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Installs the Debian 12 packages RCI Studio needs to build, test and run, skipping those present.
# Used by the README's two commands (packaging/bootstrap.sh); safe to run again.
set -eu
PACKAGES="build-essential cmake ninja-build pkg-config file dpkg-dev
 qt6-base-dev qt6-base-dev-tools qt6-charts-dev qt6-3d-dev libqt6opengl6-dev libgl-dev qt6-qpa-plugins
 libeigen3-dev liburdfdom-dev libassimp-dev
 nlohmann-json3-dev libcli11-dev libinih-dev libexpat1-dev libpugixml-dev libtinyxml2-dev
 liborocos-kdl-dev libkdl-parser-dev
 clang-14 libclang-rt-14-dev
 xvfb xauth libgl1-mesa-dri fonts-dejavu-core
 help2man lintian desktop-file-utils appstream"

missing=""
for p in $PACKAGES; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  SUDO=""
  [ "$(id -u)" = 0 ] || SUDO="sudo"
  echo "Installing:$missing"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq $missing
fi
