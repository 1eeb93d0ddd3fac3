#!/usr/bin/env python3
"""Opens a page of `ropras view` in headless chromium and checks it as a person would see it.

check_page.py --chromium PATH --page PAGE.html --screenshot OUT.png [--expect KEY=VALUE | KEY>=VALUE ...]

1. --dump-dom (with --enable-logging=stderr): the element #ropras-stats must say data-state="ready" and
   data-errors="0", every --expect must hold for its data-* attributes (e.g. boxes=19, particles>=1000), and
   chromium's log must hold no script error (an "Uncaught" exception or a console error of the page).
2. --screenshot: the PNG, decoded here (zlib and the PNG filters, no imaging library needed), must not be blank:
   the 3-D view (the right half of the picture, away from the control panel; --region full: the whole picture,
   for pages without a 3-D view) needs at least 16 distinct colours and its most common colour must cover less
   than 97 % of it.
Exit code 0 when every check passes, 1 with a message naming the failed check, 77 (skip) without chromium.
"""
import argparse
import html.parser
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

SKIP = 77


class StatsParser(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.stats = None

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if attrs.get("id") == "ropras-stats":
            self.stats = {k[5:]: v for k, v in attrs.items() if k.startswith("data-")}


def decode_png(path):
    """(width, height, rows of RGB(A) bytes) of an 8-bit RGB or RGBA PNG."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(path + ": not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", chunk)
        elif kind == b"IDAT":
            idat += chunk
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        raise ValueError("%s: unsupported PNG (depth %d, colour type %d, interlace %d)" %
                         (path, depth, colour, interlace))
    bpp = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * bpp
    rows, prev, at = [], bytearray(stride), 0
    for _ in range(height):
        kind = raw[at]
        line = bytearray(raw[at + 1:at + 1 + stride])
        at += 1 + stride
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + ((a + b) >> 1)) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return width, height, bpp, rows


def colour_variety(path, region="right"):
    width, height, bpp, rows = decode_png(path)
    counts = {}
    for y in range(0, height, 2):
        row = rows[y]
        for x in range(0 if region == "full" else width // 2, width, 2):
            key = row[x * bpp:x * bpp + 3]
            counts[key] = counts.get(key, 0) + 1
    total = sum(counts.values())
    return len(counts), max(counts.values()) / total


def check_expectation(stats, text):
    for op in (">=", "<=", "="):
        if op in text:
            key, value = text.split(op, 1)
            break
    else:
        return "bad --expect %r (KEY=VALUE, KEY>=VALUE or KEY<=VALUE)" % text
    if key not in stats:
        return "the page reports no data-%s (it reports: %s)" % (key, ", ".join(sorted(stats)))
    have = stats[key]
    try:
        h, v = float(have), float(value)
    except ValueError:
        return None if have == value else "data-%s = %r, expected %r" % (key, have, value)
    ok = h >= v if op == ">=" else h <= v if op == "<=" else h == v
    return None if ok else "data-%s = %s, expected %s %s" % (key, have, op, value)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--chromium", default="chromium")
    ap.add_argument("--page", required=True)
    ap.add_argument("--screenshot", required=True)
    ap.add_argument("--window", default="1280,800")
    ap.add_argument("--hash", default="", help="appended to the page's URL, e.g. #measure")
    ap.add_argument("--expect", action="append", default=[])
    ap.add_argument("--region", choices=["right", "full"], default="right",
                    help="part of the screenshot that must not be blank")
    a = ap.parse_args()
    chromium = shutil.which(a.chromium)
    if not chromium:
        print("SKIP: no %s on this machine (apt-get install chromium; scripts/install-deps.sh installs it)" %
              a.chromium)
        return SKIP
    url = "file://" + os.path.abspath(a.page) + a.hash
    common = [chromium, "--headless", "--disable-gpu", "--enable-unsafe-swiftshader", "--no-sandbox",
              "--hide-scrollbars", "--mute-audio",
              "--window-size=" + a.window, "--virtual-time-budget=4000"]
    with tempfile.TemporaryDirectory() as profile:
        common.append("--user-data-dir=" + profile)
        dom = subprocess.run(common + ["--enable-logging=stderr", "--v=0", "--dump-dom", url],
                             capture_output=True, text=True, timeout=120)
        shot = subprocess.run(common + ["--screenshot=" + os.path.abspath(a.screenshot), url],
                              capture_output=True, text=True, timeout=120)
    failures = []
    log = dom.stderr.splitlines()
    script_errors = [line for line in log if "Uncaught" in line or
                     ("CONSOLE" in line and ("ropras view" in line or "ropras tree page" in line))]
    if script_errors:
        failures.append("script errors in chromium's log:\n  " + "\n  ".join(script_errors))
    parser = StatsParser()
    parser.feed(dom.stdout)
    stats = parser.stats
    if stats is None:
        failures.append("no #ropras-stats in the page's DOM (chromium exit code %d)" % dom.returncode)
    else:
        print("page stats: " + " ".join("%s=%s" % kv for kv in sorted(stats.items())))
        if stats.get("state") != "ready" or stats.get("errors") != "0":
            failures.append("the page is not ready: state=%s errors=%s" % (stats.get("state"), stats.get("errors")))
        for e in a.expect:
            problem = check_expectation(stats, e)
            if problem:
                failures.append(problem)
    if not os.path.exists(a.screenshot):
        failures.append("chromium wrote no screenshot (exit code %d): %s" % (shot.returncode, shot.stderr[-500:]))
    else:
        colours, share = colour_variety(a.screenshot, a.region)
        print("screenshot %s: %d colours in the %s, the most common covers %.1f %%" %
              (a.screenshot, colours, "3-D view" if a.region == "right" else "page", 100 * share))
        if colours < 16 or share >= 0.97:
            failures.append("the screenshot is blank (%d colours, %.1f %% one colour)" % (colours, 100 * share))
    for f in failures:
        print("FAILED: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
