#!/usr/bin/env python3
"""OpenSCAD's own slice against `kerf slice` of the same .csg (issue 13 §5; docs/BENCHMARKS.md).

For three of OpenSCAD's examples, exported to .csg (tests/data/openscad/), and one torus made by
rotate_extrude (bench/openscad_torus.csg), both tools cut the
model by OpenSCAD's plane z = 0 (kerf's y = 0: kerf is y-up) and the section's area is compared
with its closed form:
  openscad  the .csg wrapped in `projection(cut = true) { … }`, run as `openscad -o cut.svg`;
            the area is the shoelace sum of the SVG's polygons (holes run the other way);
  kerf      `kerf slice MODEL.csg --plane y=0 -o cut.svg --stats`; the area is its `total: area`.
Times are wall-clock times of the whole process (start-up, reading, meshing or tracing,
writing), the best of --runs. openscad is a bench-only peer, never a kerf dependency.

    python3 bench/openscad_slice_bench.py --kerf build/kerf [--openscad openscad] [--runs 3]
"""
import argparse
import math
import os
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "tests", "data", "openscad")


def cap(R, a):
    """Area of the disc of radius R beyond a line at distance a < R from its centre."""
    return R * R * math.acos(a / R) - a * math.sqrt(R * R - a * a)


def quadrant_corner(R, a):
    """Area of the disc of radius R where x > a and y > a (a < R/√2)."""
    b = math.sqrt(R * R - a * a)
    F = lambda x: 0.5 * (x * math.sqrt(R * R - x * x) + R * R * math.asin(x / R))
    return F(b) - F(a) - a * (b - a)


# name: (file, exact area of the cut at OpenSCAD's z = 0, why)
CASES = {
    "example004": ("example004.csg", 900.0 - (math.pi * 400.0 - 4.0 * cap(20.0, 15.0)),
                   "30-square minus the radius-20 disc"),
    "CSG": ("CSG.csg", 450.0 + 4.0 * cap(10.0, 7.5),
            "15-squares ∪, ∩, − radius-10 discs"),
    "example001": ("example001.csg", 4.0 * quadrant_corner(25.0, 12.5),
                   "radius-25 disc minus a cross of half-width 12.5"),
    # An extrusion: rotate_extrude of the radius-1 circle at x = 3 (bench/openscad_torus.csg),
    # cut through its equator: the annulus 2 ≤ ρ ≤ 4.
    "torus": (os.path.join(HERE, "openscad_torus.csg"), 12.0 * math.pi,
              "rotate_extrude torus: the annulus 2..4"),
}


def shoelace_svg(path):
    """Signed polygon areas summed over an OpenSCAD SVG (M x,y L x,y … z paths)."""
    text = open(path).read()
    total = 0.0
    for d in re.findall(r'd="([^"]*)"', text):
        for loop in re.split(r"[Mm]", d)[1:]:
            pts = [tuple(map(float, p.split(","))) for p in re.findall(r"-?[\d.eE+-]+,-?[\d.eE+-]+", loop)]
            s = 0.0
            for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1]):
                s += x0 * y1 - x1 * y0
            total += 0.5 * s
    return abs(total)


def timed(cmd, runs):
    best, out = math.inf, None
    for _ in range(runs):
        start = time.perf_counter()
        out = subprocess.run(cmd, capture_output=True, text=True)
        best = min(best, time.perf_counter() - start)
        if out.returncode != 0:
            sys.exit(f"failed: {' '.join(cmd)}\n{out.stderr}")
    return best, out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--kerf", default="build/kerf")
    ap.add_argument("--openscad", default="openscad")
    ap.add_argument("--runs", type=int, default=3)
    args = ap.parse_args()
    print("| model | section | exact area | OpenSCAD area (rel. error) | OpenSCAD time | "
          "kerf area (rel. error) | kerf time |")
    print("|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for name, (file, exact, what) in CASES.items():
            csg = os.path.join(DATA, file)
            scad = os.path.join(tmp, name + ".scad")
            with open(scad, "w") as f:
                f.write("projection(cut = true) {\n" + open(csg).read() + "\n}\n")
            osvg = os.path.join(tmp, name + "_openscad.svg")
            t_os, _ = timed([args.openscad, "-o", osvg, scad], args.runs)
            a_os = shoelace_svg(osvg)
            ksvg = os.path.join(tmp, name + "_kerf.svg")
            t_k, run = timed([args.kerf, "slice", csg, "--plane", "y=0", "-o", ksvg, "--stats", "-q"], args.runs)
            a_k = float(re.search(r"total: area ([0-9.eE+-]+)", run.stderr).group(1))
            rel = lambda a: (a - exact) / exact
            print(f"| {name} | {what} | {exact:.10g} | {a_os:.8g} ({rel(a_os):+.2e}) | {t_os * 1e3:.0f} ms | "
                  f"{a_k:.12g} ({rel(a_k):+.2e}) | {t_k * 1e3:.0f} ms |")


if __name__ == "__main__":
    main()
