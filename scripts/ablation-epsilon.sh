#!/usr/bin/env bash
# The paper's first ablation figure: ROP-RAS3's success against epsilon (the share of reference targets drawn
# uniformly instead of by the dynamic heuristic) in {0, 0.2, ..., 1} on maze2d and multi-drone, with R-POMCP at
# epsilon 0 as the line to beat (a dashed horizontal line). The paper gave 3 s per planning call; the default
# here is a tenth of it, 0.3 s (`--plan-time`), or a simulation budget with SIMS=N.
# Usage: scripts/ablation-epsilon.sh [OUT_DIR] (default: ablation-epsilon/)
# Environment: EPISODES (30), SEED (1), THREADS (1), PLAN_TIME (0.3), SIMS (unset), SCENARIOS ("maze2d multi-drone"),
#              ROPRAS (build/bin/ropras), RPOMCP_PLAN_TIME (unset: R-POMCP gets the same budget as ROP-RAS3; set,
#              R-POMCP plans for that many seconds per call instead: with SIMS=1000 on maze2d, R-POMCP's 1000
#              simulations take about 5 s per call, ROP-RAS3's about 1 s, so an equal-time line is RPOMCP_PLAN_TIME=1).
# Writes OUT_DIR/<scenario>-eps<E>.jsonl, OUT_DIR/<scenario>-rpomcp.jsonl and OUT_DIR/<scenario>-epsilon.svg.
set -eu
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
R=${ROPRAS:-$here/build/bin/ropras}
out=${1:-ablation-epsilon}
budget=(--plan-time "${PLAN_TIME:-0.3}")
if [ -n "${SIMS:-}" ]; then budget=(--sims "$SIMS"); fi
episodes=(--episodes "${EPISODES:-30}" --seed "${SEED:-1}" --threads "${THREADS:-1}" --quiet)
common=("${episodes[@]}" "${budget[@]}")
mkdir -p "$out"
for scenario in ${SCENARIOS:-maze2d multi-drone}; do
  for eps in 0 0.2 0.4 0.6 0.8 1; do
    "$R" run --scenario "$scenario" --solver ropras3 --epsilon "$eps" "${common[@]}" \
      --out "$out/$scenario-eps$eps.jsonl" > /dev/null
  done
  rpomcp=("${common[@]}")
  if [ -n "${RPOMCP_PLAN_TIME:-}" ]; then rpomcp=("${episodes[@]}" --plan-time "$RPOMCP_PLAN_TIME"); fi
  "$R" run --scenario "$scenario" --solver rpomcp --epsilon 0 "${rpomcp[@]}" --out "$out/$scenario-rpomcp.jsonl" \
    > /dev/null
  "$R" plot "$out/$scenario"-eps*.jsonl "$out/$scenario-rpomcp.jsonl" --x epsilon --y success --flat R-POMCP \
    --title "$scenario: success against epsilon (ROP-RAS3; R-POMCP at epsilon 0)" --out "$out/$scenario-epsilon.svg"
done
