#!/usr/bin/env bash
# Writes the shipped Panda, robots/panda/panda.urdf and robots/panda/panda.srdf:
#   1. scripts/panda/panda.urdf.in (kinematics and limits from Franka's published parameters, one <mesh> collision
#      element per link) with its meshes taken from the MotionBenchMaker data (../shared/robots/panda/meshes;
#      read here, never copied);
#   2. `ropras spherize` replaces every mesh by a conservative sphere cover (every point of the mesh surface lies
#      inside a sphere of its link) and writes robots/panda/panda.urdf;
#   3. `ropras collision-matrix` samples that sphere model (MoveIt Setup Assistant's rules) and its pairs go into
#      scripts/panda/panda.srdf.in, giving robots/panda/panda.srdf.
# Usage: scripts/spherize-panda.sh [--ropras PATH] [--shared DIR] [--tolerance M] [--max-spheres N]
#                                  [--link LINK=M/N ...] [--samples N]
# The defaults are the shipped model's (doc/robots.md explains the choice): 0.03 m and at most 12 spheres per
# element for links 0 and 1, which rarely come close to anything; tighter covers with more spheres for the links
# that do: link2 0.02 m / 32 (so that it never reaches link4), link3 0.02 / 24, link4 0.01 / 48, link5, link6 and
# link7 0.01 / 64 (the wrist folds onto itself and reaches into shelves), the hand 0.01 / 48, each finger 0.01 / 16.
# Giving --link replaces all of these per-link settings.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ropras=$root/build/bin/ropras
shared=$root/../shared
tolerance=0.03
max_spheres=12
links=()
default_links=(--link panda_link2=0.02/32 --link panda_link3=0.02/24 --link panda_link4=0.01/48
  --link panda_link5=0.01/64
  --link panda_link6=0.01/64 --link panda_link7=0.01/64 --link panda_hand=0.01/48
  --link panda_leftfinger=0.01/16 --link panda_rightfinger=0.01/16)
samples=100000
while [ $# -gt 0 ]; do
  case "$1" in
    --ropras) ropras=$2; shift 2 ;;
    --shared) shared=$2; shift 2 ;;
    --tolerance) tolerance=$2; shift 2 ;;
    --max-spheres) max_spheres=$2; shift 2 ;;
    --link) links+=(--link "$2"); shift 2 ;;
    --samples) samples=$2; shift 2 ;;
    *) echo "spherize-panda.sh: unknown option '$1'" >&2; exit 2 ;;
  esac
done
[ ${#links[@]} -gt 0 ] || links=("${default_links[@]}")
meshes=$shared/robots/panda/meshes/collision
[ -x "$ropras" ] || { echo "spherize-panda.sh: no ropras executable at $ropras (build it, or pass --ropras)" >&2; exit 2; }
[ -d "$meshes" ] || { echo "spherize-panda.sh: no Panda collision meshes in $meshes (pass --shared)" >&2; exit 2; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sed "s|@MESH_DIR@|$(cd "$meshes" && pwd)|g" "$root/scripts/panda/panda.urdf.in" >"$tmp/panda_collision_meshes.urdf"
mkdir -p "$root/robots/panda"
"$ropras" spherize --urdf "$tmp/panda_collision_meshes.urdf" --output "$root/robots/panda/panda.urdf" \
  --tolerance "$tolerance" --max-spheres "$max_spheres" "${links[@]}"
"$ropras" collision-matrix --urdf "$root/robots/panda/panda.urdf" --samples "$samples" --seed 1 \
  --output "$tmp/pairs.xml"
awk -v pairs="$tmp/pairs.xml" '/@DISABLE_COLLISIONS@/ { while ((getline l < pairs) > 0) print l; next } { print }' \
  "$root/scripts/panda/panda.srdf.in" >"$root/robots/panda/panda.srdf"
echo "wrote $root/robots/panda/panda.srdf"
