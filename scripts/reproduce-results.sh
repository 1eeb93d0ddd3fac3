#!/usr/bin/env bash
# Reproduces the tables of doc/results.md: every scenario x solver, 30 episodes (fewer for the solvers whose
# episodes cost 80 s each, see doc/results.md), at a tenth of the paper's planning time per call.
# Usage: scripts/reproduce-results.sh [OUT_DIR] (default: results/); then `ropras table OUT_DIR/<prefix>-*.jsonl`.
# About 35 minutes on a 2-core machine.
set -u
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
R=${ROPRAS:-$here/build/bin/ropras}
out=${1:-results}
mkdir -p "$out"
cd "$out"
run() { # name episodes args...
  local name=$1 n=$2
  shift 2
  "$R" run --episodes "$n" --threads 2 --seed 1 --quiet --out "$name.jsonl" "$@" > "$name.table"
}
echo '{"termination_evidence": true}' > termination-evidence.json

LD="--scenario light-dark"
run ld-ropras3-d 30 $LD --solver ropras3
run ld-ropras3-u 30 $LD --solver ropras3 --heuristic uniform
run ld-rpomcp-d 30 $LD --solver rpomcp
run ld-bplan-d 30 $LD --solver bplan
run ld-pomcp 30 $LD --solver pomcp
run ld-refbasic 30 $LD --solver refbasic
run ld-te-ropras3-d 30 $LD --solver ropras3 --config termination-evidence.json

MD="--scenario multi-drone"
run md-ropras3-d 30 $MD --solver ropras3
run md-rpomcp-d 30 $MD --solver rpomcp
run md-bplan-d 30 $MD --solver bplan
run md-refbasic 10 $MD --solver refbasic
run md-pomcp 4 $MD --solver pomcp

MZ="--scenario maze2d"
run mz-ropras3-d 30 $MZ --solver ropras3
run mz-ropras3-u 30 $MZ --solver ropras3 --heuristic uniform
run mz-rpomcp-d 30 $MZ --solver rpomcp
run mz-bplan-d 30 $MZ --solver bplan
run mz-refbasic 10 $MZ --solver refbasic
run mz-pomcp 4 $MZ --solver pomcp
run mz-te-ropras3-d 30 $MZ --solver ropras3 --config termination-evidence.json

for k in 1 2 3 4; do
  S="--scenario random3d-$k"
  run r$k-ropras3-d 30 $S --solver ropras3
  run r$k-bplan-d 30 $S --solver bplan
  run r$k-rpomcp-d 30 $S --solver rpomcp
  run r$k-refbasic 4 $S --solver refbasic
  run r$k-pomcp 2 $S --solver pomcp
done
for group in ld mz 'r[1-4]' md; do
  "$R" table $group-*.jsonl
done
# stretch-crossing: its own table (collisions and too-close steps from the recordings)
ROPRAS="$R" "$here/scripts/crossing-results.sh" --episodes 30 --seed 1 --threads 2 --out crossing
