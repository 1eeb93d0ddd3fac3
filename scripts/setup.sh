#!/usr/bin/env bash
# One-command set-up: install the Debian packages, build (Release), then either
#   scripts/setup.sh demo   run the main job on its built-in default, or
#   scripts/setup.sh test   run the format check and the whole test suite.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$here"
mode=${1:-demo}
bash scripts/install-deps.sh
jobs=$(nproc)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$jobs"
case "$mode" in
  demo)
    build/bin/ropras demo
    ;;
  test)
    bash scripts/check-format.sh
    ctest --test-dir build --output-on-failure -j "$jobs"
    ;;
  *)
    echo "usage: scripts/setup.sh demo|test" >&2
    exit 2
    ;;
esac
