#!/usr/bin/env python3
"""Summarises search trees written by `ropras run --dump-tree DIR`: per macro level, over all given files,
belief nodes per tree, the share visited at most once, actions per belief, observation children per action,
particles per belief, primitive steps from the root; plus reference plans per simulation and the deepest
level whose nodes have more than one visit on average.

usage: scripts/tree-stats.py DIR_OR_FILES...
"""
import glob
import json
import os
import sys


def files_of(args):
    out = []
    for a in args:
        out += sorted(glob.glob(os.path.join(a, "*.json"))) if os.path.isdir(a) else [a]
    return out


def main(argv):
    files = files_of(argv[1:])
    if not files:
        sys.exit("tree-stats: no tree files given")
    levels = {}
    sims = refs = 0
    for path in files:
        with open(path) as f:
            tree = json.load(f)
        sims += tree["simulations"]
        refs += tree["reference_requested"]
        for b in tree["beliefs"]:
            l = levels.setdefault(b["depth"], {"n": 0, "once": 0, "act": 0, "obs": 0, "part": 0, "steps": 0,
                                               "visits": 0})
            l["n"] += 1
            l["once"] += b["visits"] <= 1
            l["act"] += len(b["actions"])
            l["obs"] += sum(len(tree["actions"][a]["children"]) for a in b["actions"])
            l["part"] += b["particles"]
            l["steps"] += b["steps"]
            l["visits"] += b["visits"]
    print(f"{len(files)} trees, {sims / len(files):.0f} simulations per call, "
          f"{refs / max(sims, 1):.3f} reference plans per simulation")
    print("depth | beliefs/tree | visited<=1 | visits/belief | actions/belief | obs/action | particles/belief | steps")
    for d in sorted(levels):
        l = levels[d]
        n = l["n"]
        print(f"{d:5d} | {n / len(files):12.1f} | {l['once'] / n:10.3f} | {l['visits'] / n:13.1f} | "
              f"{l['act'] / n:14.2f} | {l['obs'] / max(l['act'], 1):10.2f} | {l['part'] / n:16.1f} | "
              f"{l['steps'] / n:5.1f}")


if __name__ == "__main__":
    main(sys.argv)
