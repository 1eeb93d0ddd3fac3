#!/usr/bin/env python3
"""Where did the episodes of a navigation run end, and what did the belief know just before?

Reads the recordings of `ropras run --record DIR` (2-D and 3-D navigation scenarios: light-dark, maze2d,
random3d-*) and prints one line per episode that did not reach the goal: the final position, the danger zone
it entered (index into the scene's danger_zones, '-' for none: the horizon ran out), the steps, and the last
recorded belief before the end (its mean, its per-axis standard deviation and how far the mean was from the
true position). A summary counts the failures per danger zone. Record beliefs often (`--belief-every 5`) for
the last column to be close to the end. The belief of a terminal step is the one before that step (the filter is
not updated on the step that ended the episode), so it is compared with the position before it. Recorded
particles are unweighted draws of the filter's belief (exact with the default resample_threshold 1). Files of the
directories that are not recordings (e.g. `--dump-tree` output) are skipped with a note.

Usage: scripts/episode-endings.py DIR [DIR ...]
"""
import glob
import json
import math
import os
import re
import sys


def fail(message):
    print("episode-endings: " + message, file=sys.stderr)
    sys.exit(2)


def load(path):
    """The recording at path, or None (with a note) for a JSON file that is not one."""
    try:
        with open(path) as f:
            record = json.load(f)
    except (OSError, ValueError) as e:
        fail(f"{path}: cannot be read as JSON: {e}")
    if not isinstance(record, dict) or any(k not in record for k in ("success", "trajectory", "scene", "steps")):
        print(f"{path}: skipped, not a recording of `ropras run --record`", file=sys.stderr)
        return None
    if "danger_zones" not in record["scene"]:
        fail(f"{path}: scenario {record.get('scenario', '?')} has no danger zones (a navigation scenario is needed)")
    return record


def inside(box, p):
    return all(box[0][k] <= p[k] <= box[1][k] for k in range(len(box[0])))


def zone_order(z):
    return (1, 0) if z == "-" else (0, int(z))


def last_belief(record):
    """The last recorded belief at or before the final step: (step, mean, standard deviation per axis)."""
    beliefs = [b for b in record.get("beliefs", []) if b.get("step") is not None and b["particles"]]
    if not beliefs:
        return None
    b = max(beliefs, key=lambda b: b["step"])
    points = [p[0] for p in b["particles"]]
    dims = len(points[0])
    mean = [sum(p[k] for p in points) / len(points) for k in range(dims)]
    sd = [math.sqrt(sum((p[k] - mean[k]) ** 2 for p in points) / len(points)) for k in range(dims)]
    return b["step"], mean, sd


def main(dirs):
    if not dirs:
        fail("usage: scripts/episode-endings.py DIR [DIR ...] (directories of `ropras run --record`)")
    files = []
    for d in dirs:
        d = d.rstrip("/") or d
        if not os.path.isdir(d):
            fail(f"{d}: not a directory")
        found = sorted(glob.glob(os.path.join(d, "*.json")),
                       key=lambda f: [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", f)])
        if not found:
            fail(f"{d}: holds no recording (*.json)")
        files += found
    counts, episodes, failures = {}, 0, 0
    for path in files:
        record = load(path)
        if record is None:
            continue
        episodes += 1
        if record["success"]:
            continue
        failures += 1
        zones = record["scene"]["danger_zones"]
        end = record["trajectory"][-1][0]
        dims = record["scene"].get("dims", len(zones[0][0]) if zones else len(end))
        end = end[:dims]
        zone = next((str(i) for i, z in enumerate(zones) if inside(z, end)), "-")
        counts[zone] = counts.get(zone, 0) + 1
        line = f"{os.path.basename(path)}: steps {record['steps']}, end ({', '.join(f'{v:.2f}' for v in end)}), zone {zone}"
        belief = last_belief(record)
        if belief is not None:
            step, mean, sd = belief
            # the filter skips the update of a terminal step: its belief is that of the position before it
            at = step - 1 if step == record["steps"] and step > 0 else step
            truth = record["trajectory"][at][0][:dims]
            off = math.sqrt(sum((mean[k] - truth[k]) ** 2 for k in range(dims)))
            line += (f"; belief at step {step}: mean ({', '.join(f'{v:.2f}' for v in mean[:dims])}), "
                     f"sd ({', '.join(f'{v:.2f}' for v in sd[:dims])}), mean {off:.2f} m from the truth")
        print(line)
    summary = ", ".join(f"zone {z}: {n}" for z, n in sorted(counts.items(), key=lambda i: zone_order(i[0])))
    print(f"{failures} of {episodes} episodes failed" + (f" ({summary}; '-' = horizon)" if failures else ""))


if __name__ == "__main__":
    main(sys.argv[1:])
