#!/usr/bin/env bash
# The paper's second ablation figure: ROP-RAS3's success against the tree depth D (macro levels, `--param depth`)
# with the uniform heuristic on maze2d and multi-drone. Budget as in scripts/ablation-epsilon.sh (0.3 s per call,
# a tenth of the paper's 3 s, or SIMS=N).
# Usage: scripts/ablation-depth.sh [OUT_DIR] (default: ablation-depth/)
# Environment: EPISODES (30), SEED (1), THREADS (1), PLAN_TIME (0.3), SIMS (unset), DEPTHS ("0 1 2 4 8 16"; the x axis
#              is logarithmic when no depth is 0),
#              SCENARIOS ("maze2d multi-drone"), ROPRAS (build/bin/ropras).
# Writes OUT_DIR/<scenario>-depth<D>.jsonl and OUT_DIR/<scenario>-depth.svg.
set -eu
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
R=${ROPRAS:-$here/build/bin/ropras}
out=${1:-ablation-depth}
budget=(--plan-time "${PLAN_TIME:-0.3}")
if [ -n "${SIMS:-}" ]; then budget=(--sims "$SIMS"); fi
common=(--episodes "${EPISODES:-30}" --seed "${SEED:-1}" --threads "${THREADS:-1}" --quiet "${budget[@]}")
depths=${DEPTHS:-0 1 2 4 8 16}
log_x=(--log-x)
[[ " $depths " == *" 0 "* ]] && log_x=()  # a logarithmic axis cannot show depth 0
mkdir -p "$out"
for scenario in ${SCENARIOS:-maze2d multi-drone}; do
  for depth in $depths; do
    "$R" run --scenario "$scenario" --solver ropras3 --heuristic uniform --param depth="$depth" "${common[@]}" \
      --out "$out/$scenario-depth$depth.jsonl" > /dev/null
  done
  "$R" plot "$out/$scenario"-depth*.jsonl --x depth --y success "${log_x[@]}" \
    --title "$scenario: success against tree depth (ROP-RAS3, uniform heuristic)" --out "$out/$scenario-depth.svg"
done
