#!/usr/bin/env python3
"""A browser test of `ropras view`: makes the input, writes the page, and checks it in headless chromium.

run_case.py --ropras PATH --source DIR --work DIR --case episode|motion [--chromium NAME]

episode: `ropras run --record` a maze2d episode, `ropras view` it; the page must draw what the recording holds
         (counted here from the recording's JSON: frames, belief snapshots and particles, boxes, moving bodies).
motion:  `ropras plan` a Panda motion (robots/panda) in scenes/tabletop.yaml, `ropras view` it; the page must draw
         the scene's primitives (counted here from the YAML text), the robot's spheres (as `ropras plan` reports
         them) and one frame per joint step.
tree:    `ropras run --dump-tree` the first planning call of a maze2d episode; its HTML page, opened with #expand-all,
         must hold and draw every belief and action node of the JSON beside it (counted here), all reachable
         from the root.
Then check_page.py: no script error, the counts in #ropras-stats, a screenshot that is not blank.
Exit code 77 (skip) without chromium, or without three.js for the viewer's cases.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_page  # noqa: E402

PANDA_REQUEST = """start_state:
  joint_state:
    name: [panda_joint1, panda_joint2, panda_joint3, panda_joint4, panda_joint5, panda_joint6, panda_joint7]
    position: [0, -0.785, 0, -2.356, 0, 1.571, 0.785]
goal_constraints:
  - joint_constraints:
      - {joint_name: panda_joint1, position: -0.5}
      - {joint_name: panda_joint2, position: 0.1}
      - {joint_name: panda_joint3, position: 0.0}
      - {joint_name: panda_joint4, position: -1.5}
      - {joint_name: panda_joint5, position: 0.0}
      - {joint_name: panda_joint6, position: 1.7}
      - {joint_name: panda_joint7, position: 0.785}
"""


def run(cmd):
    print("$ " + " ".join(cmd), flush=True)
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    sys.stdout.write(done.stdout)
    sys.stdout.write(done.stderr)
    if done.returncode != 0:
        raise SystemExit("FAILED: exit code %d" % done.returncode)
    return done.stdout


def is_box(shape):
    return isinstance(shape, list) and len(shape) == 2 and all(isinstance(p, list) for p in shape) or \
        isinstance(shape, dict) and ("lo" in shape or "min" in shape or "half_extents" in shape)


def episode_expectations(recording):
    scene = recording["scene"]
    boxes = 0
    for key, value in scene.items():
        if key == "bounds" or not isinstance(value, list):
            continue
        if key == "goal" and is_box(value):
            boxes += 1
        elif value and all(is_box(s) for s in value):
            boxes += len(value)
    frames = len(recording["trajectory"])
    labels = recording.get("labels", ["robot"])
    bodies = len(labels) + (1 if "robot" in recording else 0)
    snapshots = len(recording["beliefs"])
    particles = sum(len(b["particles"]) for b in recording["beliefs"])  # one uncertain label: the robot
    return ["frames=%d" % frames, "boxes=%d" % boxes, "bodies=%d" % bodies, "snapshots=%d" % snapshots,
            "particles=%d" % particles, "paths=%d" % len(labels)]


def episode(a):
    rec = os.path.join(a.work, "rec")
    run([a.ropras, "run", "--scenario", "maze2d", "--episodes", "1", "--sims", "50", "--seed", "3",
         "--belief-every", "10", "--record", rec, "--out", os.path.join(a.work, "runs.jsonl")])
    recording_path = os.path.join(rec, "maze2d-ropras3-0.json")
    page = os.path.join(a.work, "episode.html")
    run([a.ropras, "view", recording_path, "--out", page])
    with open(recording_path) as f:
        recording = json.load(f)
    return page, episode_expectations(recording)


def motion(a):
    request = os.path.join(a.work, "panda_request.yaml")
    with open(request, "w") as f:
        f.write(PANDA_REQUEST)
    urdf = os.path.join(a.source, "robots/panda/panda.urdf")
    srdf = os.path.join(a.source, "robots/panda/panda.srdf")
    scene = os.path.join(a.source, "scenes/tabletop.yaml")
    path = os.path.join(a.work, "panda.csv")
    out = run([a.ropras, "plan", "--urdf", urdf, "--srdf", srdf, "--scene", scene, "--request", request,
               "--time", "5", "--seed", "1", "--out", path])
    spheres = int(re.search(r"\((\d+) joints, (\d+) spheres\)", out).group(2))
    page = os.path.join(a.work, "motion.html")
    run([a.ropras, "view", "--urdf", urdf, "--srdf", srdf, "--scene", scene, "--path", path, "--tip",
         "panda_hand", "--out", page])
    with open(scene) as f:
        text = f.read()
    count = {kind: len(re.findall(r"-\s*type:\s*%s\b" % kind, text)) for kind in ("box", "cylinder", "sphere")}
    with open(path) as f:
        waypoints = len(f.read().strip().splitlines()) - 1
    return page, ["boxes=%d" % count["box"], "cylinders=%d" % count["cylinder"], "spheres=%d" % count["sphere"],
                  "body-spheres=%d" % spheres, "bodies=1", "paths=1", "frames>=%d" % waypoints]


def tree_case(a):
    dump = os.path.join(a.work, "trees")
    shutil.rmtree(dump, ignore_errors=True)
    run([a.ropras, "run", "--scenario", "maze2d", "--episodes", "1", "--sims", "60", "--seed", "3", "--threads", "1",
         "--dump-tree", dump, "--dump-calls", "0", "--quiet"])
    with open(os.path.join(dump, "maze2d-ropras3-0-plan0.json")) as f:
        tree = json.load(f)
    beliefs, actions = len(tree["beliefs"]), len(tree["actions"])
    if beliefs < 2 or actions < 2:
        raise SystemExit("FAILED: the dumped tree is too small to test the page (%d beliefs, %d actions)" %
                         (beliefs, actions))
    nodes = beliefs + actions
    return os.path.join(dump, "maze2d-ropras3-0-plan0.html"), [
        "beliefs=%d" % beliefs, "actions=%d" % actions, "reachable=%d" % nodes, "drawn=%d" % nodes,
        "simulations=%d" % tree["simulations"]]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ropras", required=True)
    ap.add_argument("--source", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--case", choices=["episode", "motion", "tree"], required=True)
    ap.add_argument("--chromium", default="chromium")
    a = ap.parse_args()
    if not shutil.which(a.chromium):
        print("SKIP: no %s on this machine (apt-get install chromium; scripts/install-deps.sh installs it)" %
              a.chromium)
        return check_page.SKIP
    if a.case != "tree" and not os.path.exists("/usr/share/javascript/three/three.min.js"):
        print("SKIP: no three.js (apt-get install libjs-three; scripts/install-deps.sh installs it)")
        return check_page.SKIP
    os.makedirs(a.work, exist_ok=True)
    page, expect = {"episode": episode, "motion": motion, "tree": tree_case}[a.case](a)
    args = ["--chromium", a.chromium, "--page", page, "--screenshot", page[:-5] + ".png"]
    if a.case == "tree":
        args += ["--hash", "#expand-all", "--region", "full"]
    for e in expect:
        args += ["--expect", e]
    print("expected from the inputs: " + " ".join(expect))
    sys.argv = ["check_page.py"] + args
    return check_page.main()


if __name__ == "__main__":
    sys.exit(main())
