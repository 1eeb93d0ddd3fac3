#!/usr/bin/env bash
# The stretch-crossing table of doc/results.md: ROP-RAS3, R-POMCP and B-plan (uniform heuristic, as in the demo)
# at the scenario's default budget (planning.plan_seconds = 0.28 s per call, for at most 0.3 s), N episodes each;
# per solver: success % (standard error), episodes that ended in a collision with the pedestrian and with a table
# or wall, too-close steps per episode, steps, planning time per call. Collisions and too-close steps are counted
# from the recordings' "events".
# Usage: scripts/crossing-results.sh [--episodes N] [--seed S] [--threads T] [--out DIR] [--write-doc]
#   defaults: 30 episodes, seed 1, 2 threads, results/crossing; --write-doc replaces the table in
#   doc/results.md (between its stretch-crossing markers) instead of printing it only.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ropras=${ROPRAS:-$root/build/bin/ropras}
episodes=30
seed=1
threads=2
out=results/crossing
write_doc=0
while [ $# -gt 0 ]; do
  case "$1" in
    --episodes) episodes=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --write-doc) write_doc=1; shift ;;
    *) echo "crossing-results.sh: unknown option '$1'" >&2; exit 2 ;;
  esac
done
[ -x "$ropras" ] || { echo "crossing-results.sh: no ropras executable at $ropras" >&2; exit 2; }
mkdir -p "$out"
for solver in ropras3 rpomcp bplan; do
  rm -rf "$out/$solver" "$out/$solver.jsonl"
  "$ropras" run --scenario stretch-crossing --solver "$solver" --heuristic uniform --episodes "$episodes" \
    --seed "$seed" --threads "$threads" --quiet --record "$out/$solver" --out "$out/$solver.jsonl" >/dev/null
done
table=$(python3 - "$out" "$episodes" "$seed" <<'PY'
import glob, json, math, sys
out, episodes, seed = sys.argv[1], int(sys.argv[2]), sys.argv[3]
names = {"ropras3": "ROP-RAS3", "rpomcp": "R-POMCP", "bplan": "B-plan"}
def mean_se(xs):
    n = len(xs)
    m = sum(xs) / n
    v = sum((x - m) ** 2 for x in xs) / (n - 1) if n > 1 else 0.0
    return m, math.sqrt(v / n)
rows = ["| Solver | Episodes | Success % (s.e.) | Pedestrian collisions | Table / wall collisions | "
        "Too-close steps / episode (s.e.) | Steps (s.e.) | Plan time per call (s) | Return (s.e.) |",
        "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"]
for solver, name in names.items():
    records = [json.loads(l) for l in open(f"{out}/{solver}.jsonl") if l.strip()]
    recs = [json.load(open(f)) for f in sorted(glob.glob(f"{out}/{solver}/*.json"))]
    n = len(records)
    p = sum(r["success"] for r in records) / n
    ped = sum(any(e["event"] == "pedestrian-collision" for e in r["events"]) for r in recs)
    obs = sum(any(e["event"] == "obstacle-collision" for e in r["events"]) for r in recs)
    close = mean_se([sum(e["event"] == "too-close" for e in r["events"]) for r in recs])
    steps = mean_se([r["steps"] for r in records])
    ret = mean_se([r["undiscounted_return"] for r in records])
    plan = sum(r["plan_time_s"] for r in records) / n
    rows.append(f"| {name} | {n} | {100 * p:.1f} ({100 * math.sqrt(p * (1 - p) / n):.1f}) | {ped} | {obs} | "
                f"{close[0]:.2f} ({close[1]:.2f}) | {steps[0]:.1f} ({steps[1]:.1f}) | {plan:.3f} | "
                f"{ret[0]:.1f} ({ret[1]:.1f}) |")
print("\n".join(rows))
print(f"\n`scripts/crossing-results.sh --episodes {episodes} --seed {seed}` (uniform heuristic, "
      "VectorizedRRTConnect reference planner, the default 0.28 s budget per planning call).")
PY
)
echo "$table"
if [ "$write_doc" = 1 ]; then
  python3 - "$root/doc/results.md" "$table" <<'PY'
import sys
path, table = sys.argv[1], sys.argv[2]
text = open(path).read()
begin, end = "<!-- stretch-crossing table begin -->", "<!-- stretch-crossing table end -->"
if begin not in text or end not in text:
    sys.exit(f"crossing-results.sh: {path} has no stretch-crossing markers")
head, rest = text.split(begin, 1)
_, tail = rest.split(end, 1)
open(path, "w").write(head + begin + "\n" + table + "\n" + end + tail)
PY
  echo "wrote the table into $root/doc/results.md"
fi
