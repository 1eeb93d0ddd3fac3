#!/usr/bin/env bash
# The load time and drawing rate of a `ropras view` page in headless chromium (issue 21's target: an 800-step
# episode with 200 belief particles per snapshot loads in under 2 s).
#   scripts/bench-viewer.sh [BUILD_DIR] [RUNS]
# Records a light-dark episode of 800 steps (horizon 800, POMCP with 5 simulations per step, so it never reaches
# the goal) with the belief of every step (200 particles), writes its page, opens it RUNS times (default 5) and
# prints each run's figures from #ropras-stats (load-ms: navigation start to the first picture; draw-fps: 60 frames
# drawn back to back, each waited for, in the page's #measure mode) and their medians.
set -euo pipefail
build=${1:-build}
runs=${2:-5}
ropras=$build/bin/ropras
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo '{"horizon": 800}' > "$work/h800.json"
"$ropras" run --scenario light-dark --solver pomcp --config "$work/h800.json" --episodes 1 --sims 5 --seed 1 \
  --belief-every 1 --max-particles 200 --record "$work/rec" --out "$work/runs.jsonl" --quiet > /dev/null
"$ropras" view "$work/rec/light-dark-pomcp-0.json" --out "$work/episode.html"
loads=() fps=()
for ((i = 0; i < runs; i++)); do
  stats=$(chromium --headless --disable-gpu --enable-unsafe-swiftshader --no-sandbox --window-size=1280,800 \
    --user-data-dir="$work/profile" --virtual-time-budget=5000 --dump-dom "file://$work/episode.html#measure" \
    2> /dev/null | grep -o '<div id="ropras-stats"[^>]*>')
  load=$(grep -o 'data-load-ms="[0-9.]*"' <<< "$stats" | grep -o '[0-9.]*')
  rate=$(grep -o 'data-draw-fps="[0-9.]*"' <<< "$stats" | grep -o '[0-9.][0-9.]*')
  frames=$(grep -o 'data-frames="[0-9]*"' <<< "$stats" | grep -o '[0-9]*')
  particles=$(grep -o 'data-max-particles="[0-9]*"' <<< "$stats" | grep -o '[0-9]*')
  echo "run $((i + 1)): $frames frames, $particles particles per snapshot: load ${load} ms, draws ${rate} frames/s"
  loads+=("$load") fps+=("$rate")
done
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
echo "median over $runs runs: load $(median "${loads[@]}") ms, draws $(median "${fps[@]}") frames/s" \
  "(page $(du -k "$work/episode.html" | cut -f1) KiB; load average $(cut -d' ' -f1 /proc/loadavg))"
