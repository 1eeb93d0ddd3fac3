#!/usr/bin/env python3
"""Writes the two synthetic benchmark and test robots of test/data/robots/ from the shipped Panda
(robots/panda/panda.{urdf,srdf}: Franka's published kinematics, conservative sphere cover):

  panda_torso/  the Panda on a prismatic torso: a fixed base column and a lift joint (0 .. 0.4 m along z, as a
                Fetch's torso), 8 planned joints (1 prismatic + 7 revolute);
  dual_panda/   two Pandas on a common torso, 0.25 m to either side, turned +-90 degrees about z (left_ /
                right_ prefixes): 14 planned joints, group "both_arms" (and "left_arm", "right_arm").

Each SRDF keeps the Panda's disable_collisions pairs within each arm (prefixed) and adds the pairs a base link
cannot reach. Usage (from the repository root): python3 scripts/make-test-robots.py
"""
import copy
import pathlib
import re
import xml.etree.ElementTree as ET

ROOT = pathlib.Path(__file__).resolve().parent.parent
PANDA_URDF = ROOT / "robots/panda/panda.urdf"
PANDA_SRDF = ROOT / "robots/panda/panda.srdf"
OUT = ROOT / "test/data/robots"

HEADER = ("<!-- Written by scripts/make-test-robots.py from robots/panda/panda.urdf (ropras's Panda, Franka's published\n"
          "     kinematics, conservative sphere cover). A synthetic robot for tests and benchmarks: {what} -->\n")


def panda_parts(prefix):
    """the Panda's links and joints, names prefixed (the link and joint elements of robots/panda/panda.urdf)"""
    # the shipped file's comments hold "--" (command lines), which strict XML parsers refuse: drop them first
    robot = ET.fromstring(re.sub(r"<!--.*?-->", "", PANDA_URDF.read_text(), flags=re.S))
    links, joints = [], []
    for element in robot:
        e = copy.deepcopy(element)
        if e.tag == "link":
            e.set("name", prefix + e.get("name"))
            links.append(e)
        elif e.tag == "joint":
            e.set("name", prefix + e.get("name"))
            for tag in ("parent", "child"):
                e.find(tag).set("link", prefix + e.find(tag).get("link"))
            joints.append(e)
    return links, joints


def box_link(name, size, xyz):
    """a link whose collision geometry is spheres along a vertical column (the model takes spheres)"""
    link = ET.Element("link", name=name)
    x, y, z0 = xyz
    count = max(1, int(round(size / 0.1)))
    for i in range(count):
        c = ET.SubElement(link, "collision")
        ET.SubElement(c, "origin", xyz=f"{x} {y} {z0 + (i + 0.5) * size / count:.4f}", rpy="0 0 0")
        g = ET.SubElement(c, "geometry")
        ET.SubElement(g, "sphere", radius="0.09")
    return link


def joint(name, kind, parent, child, xyz="0 0 0", rpy="0 0 0", axis=None, limits=None):
    j = ET.Element("joint", name=name, type=kind)
    ET.SubElement(j, "parent", link=parent)
    ET.SubElement(j, "child", link=child)
    ET.SubElement(j, "origin", xyz=xyz, rpy=rpy)
    if axis:
        ET.SubElement(j, "axis", xyz=axis)
    if limits:
        ET.SubElement(j, "limit", lower=str(limits[0]), upper=str(limits[1]), effort="100", velocity="0.1")
    return j


def torso(robot):
    """base (a column of spheres up to 0.5 m) and a lift link carried by the prismatic torso joint"""
    robot.append(box_link("base_link", 0.5, (0.0, 0.0, 0.0)))
    robot.append(box_link("torso_link", 0.2, (-0.15, 0.0, 0.0)))
    robot.append(joint("torso_lift_joint", "prismatic", "base_link", "torso_link", xyz="0 0 0.5", axis="0 0 1",
                       limits=(0.0, 0.4)))


def write(name, robot, what):
    folder = OUT / name
    folder.mkdir(parents=True, exist_ok=True)
    ET.indent(robot, space="  ")
    text = '<?xml version="1.0"?>\n' + HEADER.format(what=what) + ET.tostring(robot, encoding="unicode") + "\n"
    (folder / (name + ".urdf")).write_text(text)


def panda_disabled_pairs(prefix):
    srdf = ET.fromstring(re.sub(r"<!--.*?-->", "", PANDA_SRDF.read_text(), flags=re.S))
    return [(prefix + d.get("link1"), prefix + d.get("link2"), d.get("reason"))
            for d in srdf.iter("disable_collisions")]


def write_srdf(name, groups, pairs, what):
    robot = ET.Element("robot", name=name)
    for group, chains in groups:
        g = ET.SubElement(robot, "group", name=group)
        for item in chains:
            if item[0] == "chain":
                ET.SubElement(g, "chain", base_link=item[1], tip_link=item[2])
            elif item[0] == "joint":
                ET.SubElement(g, "joint", name=item[1])
            else:
                ET.SubElement(g, "group", name=item[1])
    for a, b, reason in pairs:
        ET.SubElement(robot, "disable_collisions", link1=a, link2=b, reason=reason)
    ET.indent(robot, space="  ")
    text = '<?xml version="1.0"?>\n' + HEADER.format(what=what) + ET.tostring(robot, encoding="unicode") + "\n"
    (OUT / name / (name + ".srdf")).write_text(text)


def panda_torso():
    robot = ET.Element("robot", name="panda_torso")
    torso(robot)
    links, joints = panda_parts("")
    robot.extend(links)
    robot.append(joint("arm_mount", "fixed", "torso_link", "panda_link0", xyz="0.1 0 0.1"))
    robot.extend(joints)
    what = "the Panda on a prismatic torso (8 planned joints)."
    write("panda_torso", robot, what)
    pairs = panda_disabled_pairs("") + [("base_link", "torso_link", "Adjacent"),
                                        ("torso_link", "panda_link0", "Adjacent"),
                                        ("base_link", "panda_link0", "Never")]
    write_srdf("panda_torso", [("arm_with_torso", [("joint", "torso_lift_joint"),
                                                   ("chain", "panda_link0", "panda_link8")])], pairs, what)


def dual_panda():
    robot = ET.Element("robot", name="dual_panda")
    torso(robot)
    for side, y, yaw in (("left_", 0.25, 1.5708), ("right_", -0.25, -1.5708)):
        links, joints = panda_parts(side)
        robot.extend(links)
        robot.append(joint(side + "arm_mount", "fixed", "torso_link", side + "panda_link0", xyz=f"0.05 {y} 0.15",
                           rpy=f"0 0 {yaw}"))
        robot.extend(joints)
    what = "two Pandas on a prismatic torso (14 planned arm joints, the torso held)."
    write("dual_panda", robot, what)
    pairs = panda_disabled_pairs("left_") + panda_disabled_pairs("right_")
    pairs += [("base_link", "torso_link", "Adjacent")]
    for side in ("left_", "right_"):
        pairs += [("torso_link", side + "panda_link0", "Adjacent"), ("base_link", side + "panda_link0", "Never")]
    pairs += [("left_panda_link0", "right_panda_link0", "Never")]
    write_srdf("dual_panda", [("left_arm", [("chain", "left_panda_link0", "left_panda_link8")]),
                              ("right_arm", [("chain", "right_panda_link0", "right_panda_link8")]),
                              ("both_arms", [("group", "left_arm"), ("group", "right_arm")])], pairs, what)


if __name__ == "__main__":
    panda_torso()
    dual_panda()
