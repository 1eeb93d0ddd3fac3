#!/usr/bin/env bash
# Writes the shipped Stretch-like robot, robots/stretch/stretch.urdf: `ropras spherize` replaces every <box> of
# scripts/stretch/stretch.urdf.in (written from the published Stretch 3 dimensions, doc/robots.md) by a
# conservative sphere cover (every point of the box surface lies inside a sphere of its link).
# Usage: scripts/spherize-stretch.sh [--ropras PATH] [--tolerance M] [--max-spheres N] [--link LINK=M/N ...]
# The defaults are the shipped model's: the base shell (the part that meets the pedestrian and the tables) 0.015 m
# and at most 64 spheres; the mast, head and lift carriage, which stay inside the base footprint, 0.03 m / 12, 8, 8;
# the arm and the wrist, which reach 6.5 cm beyond the base side, 0.02 m / 8. Giving --link replaces these.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ropras=$root/build/bin/ropras
tolerance=0.02
max_spheres=8
links=()
default_links=(--link base_link=0.015/64 --link link_mast=0.03/12 --link link_head=0.03/8 --link link_lift=0.03/8
  --link link_arm=0.02/8 --link link_wrist=0.02/8)
while [ $# -gt 0 ]; do
  case "$1" in
    --ropras) ropras=$2; shift 2 ;;
    --tolerance) tolerance=$2; shift 2 ;;
    --max-spheres) max_spheres=$2; shift 2 ;;
    --link) links+=(--link "$2"); shift 2 ;;
    *) echo "spherize-stretch.sh: unknown option '$1'" >&2; exit 2 ;;
  esac
done
[ ${#links[@]} -gt 0 ] || links=("${default_links[@]}")
[ -x "$ropras" ] || { echo "spherize-stretch.sh: no ropras executable at $ropras (build it, or pass --ropras)" >&2; exit 2; }
mkdir -p "$root/robots/stretch"
"$ropras" spherize --urdf "$root/scripts/stretch/stretch.urdf.in" --output "$root/robots/stretch/stretch.urdf" \
  --tolerance "$tolerance" --max-spheres "$max_spheres" "${links[@]}"
