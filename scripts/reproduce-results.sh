#!/usr/bin/env bash
# Reproduces the navigation tables of doc/results.md: every scenario x solver, 30 episodes (fewer for the solvers
# whose episodes run to the horizon, see doc/results.md), seed 1, 2 threads (SEED, EPISODES and THREADS change them).
# Usage: scripts/reproduce-results.sh [OUT_DIR] (default: results/); then `ropras table OUT_DIR/<prefix>-*.jsonl`.
# Environment:
#   BUDGET=tenth (default) a tenth of the paper's planning time per call (each scenario's default: Light-Dark
#                0.01 s, the others 0.1 s); about 35 minutes on a 2-core machine
#   BUDGET=paper the paper's own time per call (Light-Dark 0.1 s, the others 1 s); about ten times as long
#   SCENARIOS    the scenarios to run, any of "light-dark multi-drone maze2d random3d stretch-crossing" (default:
#                all of them; random3d stands for its four problems)
#   SOLVERS      the solvers to run, any of "ropras3 rpomcp bplan pomcp refbasic" (default: all of them)
#   SEED         the run seed (default 1; doc/results.md's third Random3D seed is 6161)
#   EPISODES     episodes of the rows that have 30 by default (POMCP and Ref-Basic on the long horizons keep
#                their own counts)
#   THREADS      worker threads per run (default 2; the time-budgeted rows depend on the load, see
#                doc/running-experiments.md)
#   ROPRAS       the ropras executable (default: build/bin/ropras)
set -u
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
R=${ROPRAS:-$here/build/bin/ropras}
out=${1:-results}
budget=${BUDGET:-tenth}
scenarios=" ${SCENARIOS:-light-dark multi-drone maze2d random3d stretch-crossing} "
solvers=" ${SOLVERS:-ropras3 rpomcp bplan pomcp refbasic} "
seed=${SEED:-1}
episodes=${EPISODES:-30}
threads=${THREADS:-2}
for value in "$seed" "$episodes" "$threads"; do
  [[ "$value" =~ ^[0-9]+$ ]] || { echo "reproduce-results.sh: SEED, EPISODES and THREADS must be whole numbers, not '$value'" >&2; exit 2; }
done
case "$budget" in
  tenth) ld_time=() other_time=() ;;
  paper) ld_time=(--plan-time 0.1) other_time=(--plan-time 1) ;;
  *) echo "reproduce-results.sh: BUDGET must be tenth or paper, not '$budget'" >&2; exit 2 ;;
esac
[ -x "$R" ] || { echo "reproduce-results.sh: no ropras executable at $R" >&2; exit 2; }
mkdir -p "$out"
cd "$out"
wanted() { [[ "$scenarios" == *" $1 "* ]]; }
run() { # name episodes args... (--solver S among them)
  local name=$1 n=$2 solver
  shift 2
  solver=$(printf '%s\n' "$@" | grep -A1 -x -- --solver | tail -n 1)
  [[ "$solvers" == *" $solver "* ]] || return 0
  "$R" run --episodes "$n" --threads "$threads" --seed "$seed" --quiet --out "$name.jsonl" "$@" > "$name.table"
}
echo '{"termination_evidence": true}' > termination-evidence.json

# The rows of Light-Dark and Maze2D: ROP-RAS3 (dynamic, uniform, with termination evidence), R-POMCP, B-plan, and
# POMCP and Ref-Basic with their own episode counts. Usage: goal_rows PREFIX POMCP_EPISODES REFBASIC_EPISODES ARGS...
goal_rows() {
  local p=$1 pomcp_n=$2 refbasic_n=$3
  shift 3
  run "$p-ropras3-d" "$episodes" "$@" --solver ropras3
  run "$p-ropras3-u" "$episodes" "$@" --solver ropras3 --heuristic uniform
  run "$p-rpomcp-d" "$episodes" "$@" --solver rpomcp
  run "$p-bplan-d" "$episodes" "$@" --solver bplan
  run "$p-refbasic" "$refbasic_n" "$@" --solver refbasic
  run "$p-pomcp" "$pomcp_n" "$@" --solver pomcp
  run "$p-te-ropras3-d" "$episodes" "$@" --solver ropras3 --config termination-evidence.json
}

if wanted light-dark; then
  goal_rows ld "$episodes" "$episodes" --scenario light-dark "${ld_time[@]}"
fi

if wanted multi-drone; then
  MD=(--scenario multi-drone "${other_time[@]}")
  run md-ropras3-d "$episodes" "${MD[@]}" --solver ropras3
  run md-rpomcp-d "$episodes" "${MD[@]}" --solver rpomcp
  run md-bplan-d "$episodes" "${MD[@]}" --solver bplan
  run md-refbasic 10 "${MD[@]}" --solver refbasic
  run md-pomcp 4 "${MD[@]}" --solver pomcp
fi

if wanted maze2d; then
  goal_rows mz 4 10 --scenario maze2d "${other_time[@]}"
fi

if wanted random3d; then
  for k in 1 2 3 4; do
    S=(--scenario "random3d-$k" "${other_time[@]}")
    run "r$k-ropras3-d" "$episodes" "${S[@]}" --solver ropras3
    run "r$k-bplan-d" "$episodes" "${S[@]}" --solver bplan
    run "r$k-rpomcp-d" "$episodes" "${S[@]}" --solver rpomcp
    run "r$k-refbasic" 4 "${S[@]}" --solver refbasic
    run "r$k-pomcp" 2 "${S[@]}" --solver pomcp
  done
fi

for group in ld md mz 'r[1-4]'; do
  files=$(compgen -G "$group-*.jsonl") && "$R" table $files
done
# stretch-crossing: its own table (collisions and too-close steps from the recordings), at its own budget
if wanted stretch-crossing; then
  ROPRAS="$R" "$here/scripts/crossing-results.sh" --episodes "$episodes" --seed "$seed" --threads "$threads" --out crossing
fi
