#!/usr/bin/env bash
# One-command set-up: install the Debian packages, build (Release), then either
#   scripts/setup.sh demo   run the main job (a short Light-Dark experiment with ROP-RAS3), or
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
    # The main job: a short Light-Dark experiment with ROP-RAS3 (10 episodes, 0.01 s per planning call),
    # one JSON line per episode in light-dark.jsonl, then the paper's table.
    build/bin/ropras run --scenario light-dark --solver ropras3 --episodes 10 --out light-dark.jsonl
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
