#!/usr/bin/env bash
# Installs everything ropras needs to build and test, from Debian 12 packages only. Run as root.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
packages=(
  build-essential cmake git clang-format
  libompl-dev libfcl-dev liburdfdom-dev libtinyxml2-dev libassimp-dev libbullet-dev libeigen3-dev
  libyaml-cpp-dev libcli11-dev nlohmann-json3-dev
  libgtest-dev libbenchmark-dev
  liborocos-kdl-dev libkdl-parser-dev  # only for `ropras bench-ik` and the tests (the KDL comparison)
  ompl-demos  # /usr/bin/ompl_benchmark_statistics: bench-mbm --ompl-log into Planner Arena's database (a test)
  libjs-three  # three.js, embedded into the pages of `ropras view` (read at run time from /usr/share/javascript/three)
  chromium python3  # the browser tests of `ropras view` (test/browser: headless chromium, a PNG check in python3)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if ((${#missing[@]})); then
  apt-get update
  apt-get install -y --no-install-recommends "${missing[@]}"
fi
