#!/usr/bin/env python3
"""Accuracy of `kerf slice` against analytic plane sections (issue 11 §2; docs/accuracy.md).

For each scene in bench/slice_accuracy/ and each tolerance, runs
    kerf slice SCENE PLANE -o OUT.dxf --tolerance T --stats
reads the closed polylines back from the DXF (every coordinate is written exactly) and
compares them with the section's closed form:
  area error      shoelace area of the loops (signed: holes run clockwise) minus the exact area;
  H(contour→true) the largest distance to the true boundary curve from every vertex and from
                  16 points along every edge (t = k/16, so each chord's middle is one of them);
  H(true→contour) the largest distance to the polygon from points on the true curve, 16 per
                  edge of the drawing spread evenly over the curve's parameter.
Distances to a circle are | |p - c| - r |; to the ellipse the nearest point is solved for
(bisection on the foot-point equation, below); to a box minus circles the minimum over its
rectangle and circles. Python standard library only. Timings come from --stats.

    python3 bench/slice_accuracy.py --kerf build/kerf [--runs 3] [--markdown]
"""
import argparse
import math
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "slice_accuracy")
TOLERANCES = [1e-3, 1e-5, 1e-7, 1e-9]
EDGE_SAMPLES = 16


# ---- true boundary pieces: distance from a point, and points along the piece ----------

class Circle:
    def __init__(self, cx, cy, r):
        self.cx, self.cy, self.r = cx, cy, r

    def distance(self, x, y):
        return abs(math.hypot(x - self.cx, y - self.cy) - self.r)

    def length(self):
        return 2 * math.pi * self.r

    def samples(self, n):
        return [(self.cx + self.r * math.cos(2 * math.pi * k / n),
                 self.cy + self.r * math.sin(2 * math.pi * k / n)) for k in range(n)]


def segment_distance(px, py, ax, ay, bx, by):
    dx, dy = bx - ax, by - ay
    d2 = dx * dx + dy * dy
    t = 0.0 if d2 == 0 else max(0.0, min(1.0, ((px - ax) * dx + (py - ay) * dy) / d2))
    return math.hypot(px - (ax + t * dx), py - (ay + t * dy))


class Rectangle:
    """The outline of [x0, x1] x [y0, y1]."""

    def __init__(self, x0, y0, x1, y1):
        self.c = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]

    def distance(self, x, y):
        return min(segment_distance(x, y, *self.c[i], *self.c[(i + 1) % 4]) for i in range(4))

    def length(self):
        return 2 * (self.c[2][0] - self.c[0][0] + self.c[2][1] - self.c[0][1])

    def samples(self, n):
        out = []
        for i in range(4):
            (ax, ay), (bx, by) = self.c[i], self.c[(i + 1) % 4]
            m = max(1, n // 4)
            out += [(ax + (bx - ax) * k / m, ay + (by - ay) * k / m) for k in range(m)]
        return out


class Ellipse:
    """Axis-aligned ellipse about (cx, cy) with semi-axes a along x and b along y."""

    def __init__(self, cx, cy, a, b):
        self.cx, self.cy, self.a, self.b = cx, cy, a, b

    def distance(self, x, y):
        u, v, a, b = abs(x - self.cx), abs(y - self.cy), self.a, self.b
        if a < b:  # the foot-point equation below wants the major axis along u
            u, v, a, b = v, u, b, a
        fx, fy = ellipse_foot(u, v, a, b)
        return math.hypot(u - fx, v - fy)

    def length(self):  # Ramanujan's second approximation: only to size the sampling
        h = ((self.a - self.b) / (self.a + self.b)) ** 2
        return math.pi * (self.a + self.b) * (1 + 3 * h / (10 + math.sqrt(4 - 3 * h)))

    def samples(self, n):
        return [(self.cx + self.a * math.cos(2 * math.pi * k / n),
                 self.cy + self.b * math.sin(2 * math.pi * k / n)) for k in range(n)]


def ellipse_foot(u, v, a, b):
    """Nearest point to (u, v), u, v >= 0, on x²/a² + y²/b² = 1 with a >= b.

    The foot (x, y) satisfies x = a²u/(t + a²), y = b²v/(t + b²) for the multiplier t of the
    normal; for v > 0 the root of F(t) = (au/(t+a²))² + (bv/(t+b²))² - 1 on t > -b² is unique
    (F falls strictly) and lies in [-b² + bv, -b² + √(a²u² + b²v²)], where F ≥ 0 and ≤ 0: found
    by bisection to the last bit. On v = 0 the foot leaves the axis only inside the evolute."""
    if v > 0:
        lo, hi = -b * b + b * v, -b * b + math.hypot(a * u, b * v)
        for _ in range(2000):
            mid = 0.5 * (lo + hi)
            if mid <= lo or mid >= hi:
                break
            f = (a * u / (mid + a * a)) ** 2 + (b * v / (mid + b * b)) ** 2 - 1
            if f > 0:
                lo = mid
            else:
                hi = mid
        t = 0.5 * (lo + hi)
        return a * a * u / (t + a * a), b * b * v / (t + b * b)
    if u < (a * a - b * b) / a:
        x = a * a * u / (a * a - b * b)
        return x, b * math.sqrt(max(0.0, 1 - (x / a) ** 2))
    return a, 0.0


def check_ellipse_distance():
    """The foot-point solver against brute force (dense sampling refined by golden section)."""
    import random
    rng = random.Random(7)
    e = Ellipse(0.3, -0.2, 0.9, 0.5)
    for _ in range(200):
        x, y = rng.uniform(-1.5, 2.0), rng.uniform(-1.2, 0.9)
        g = lambda th: math.hypot(x - e.cx - e.a * math.cos(th), y - e.cy - e.b * math.sin(th))
        best = min(range(4096), key=lambda k: g(2 * math.pi * k / 4096))
        lo, hi = 2 * math.pi * (best - 1) / 4096, 2 * math.pi * (best + 1) / 4096
        for _ in range(200):
            m1, m2 = lo + (hi - lo) * 0.381966, hi - (hi - lo) * 0.381966
            if g(m1) < g(m2):
                hi = m2
            else:
                lo = m1
        brute = g(0.5 * (lo + hi))
        if abs(brute - e.distance(x, y)) > 1e-12:
            raise AssertionError(f"ellipse distance at ({x}, {y}): {e.distance(x, y)} vs {brute}")


# ---- the five cases ----------------------------------------------------------------

def cases():
    # Cone of apex height H = 2, base radius 1 (slope t = 1/2), plane z = 0.8 + s x, s = 1/2,
    # through (0, 0, 0.8) with normal (-s, 0, 1): u runs along (1, 0, s)/√(1+s²), v along y.
    # x² + y² = t²(c - s x)², c = 1.2, is an ellipse with k = 1 - t²s²: centre
    # u0 = -t²cs√(1+s²)/k, semi-axes A = tc√(1+s²)/k along u and B = tc/√k along v.
    t, s, c = 0.5, 0.5, 1.2
    k = 1 - t * t * s * s
    cone_a, cone_b = t * c * math.sqrt(1 + s * s) / k, t * c / math.sqrt(k)
    cone_u0 = -t * t * c * s * math.sqrt(1 + s * s) / k
    z = float("0.999999")
    pole_r = math.sqrt((1 - z) * (1 + z))  # 1 - z is exact (Sterbenz)
    R, r = 1.2, 1.2 - 1.2 / 10
    return [
        # name, scene, plane options, model size, exact area, boundary pieces
        ("cup wall (annulus)", "cup_wall.kerf", ["--plane", "y=1.2"], 2.4,
         math.pi * (R * R - r * r), [Circle(0, 0, R), Circle(0, 0, r)]),
        ("box minus circles", "box_minus_circles.kerf", ["--plane", "z=0.25"], 4.0,
         8 - math.pi * (0.25 + 0.09), [Rectangle(0, 0, 4, 2), Circle(1, 1, 0.5), Circle(3, 1, 0.3)]),
        ("torus through its axis", "torus_axis.kerf", ["--plane", "x=0"], 5.0,
         2 * math.pi * 0.25, [Circle(0, 2, 0.5), Circle(0, -2, 0.5)]),
        ("cone, oblique (ellipse)", "cone_oblique.kerf",
         ["--point", "0,0,0.8", "--normal", "-0.5,0,1"], 2.0,
         math.pi * cone_a * cone_b, [Ellipse(cone_u0, 0, cone_a, cone_b)]),
        ("sphere near its pole", "sphere_pole.kerf", ["--plane", "z=0.999999"], 2.0,
         math.pi * pole_r * pole_r, [Circle(0, 0, pole_r)]),
    ]


# ---- reading kerf's output -----------------------------------------------------------

def read_dxf_loops(path):
    """The closed LWPOLYLINEs of a DXF as lists of (x, y); bulges (code 42) are refused."""
    with open(path) as f:
        lines = [ln.strip() for ln in f]
    pairs = list(zip(lines[0::2], lines[1::2]))
    loops, cur, x = [], None, None
    for code, value in pairs:
        if code == "0":
            if cur is not None:
                loops.append(cur)
            cur = [] if value == "LWPOLYLINE" else None
        elif cur is not None:
            if code == "10":
                x = float(value)
            elif code == "20":
                cur.append((x, float(value)))
            elif code == "42" and float(value) != 0:
                raise ValueError(f"{path}: a bulge (arc) in a polyline; this reader wants chords")
    return loops


def parse_stats(text):
    slice_ms = float(re.search(r"slice ([0-9.]+) ms", text).group(1))
    absolute = float(re.search(r"absolute ([0-9.e+-]+)\)", text).group(1))
    kerf_area = float(re.search(r"total: area ([0-9.e+-]+)", text).group(1))
    return slice_ms, absolute, kerf_area


# ---- measures ------------------------------------------------------------------------

def shoelace(loop):
    x0, y0 = loop[0]
    n = len(loop)
    return 0.5 * math.fsum((loop[i][0] - x0) * (loop[(i + 1) % n][1] - y0)
                           - (loop[(i + 1) % n][0] - x0) * (loop[i][1] - y0) for i in range(n))


def contour_to_true(loops, pieces):
    worst = worst_vertex = 0.0
    for loop in loops:
        n = len(loop)
        for i in range(n):
            (ax, ay), (bx, by) = loop[i], loop[(i + 1) % n]
            for k in range(EDGE_SAMPLES):
                f = k / EDGE_SAMPLES
                x, y = ax + (bx - ax) * f, ay + (by - ay) * f
                d = min(p.distance(x, y) for p in pieces)
                worst = max(worst, d)
                if k == 0:
                    worst_vertex = max(worst_vertex, d)
    return worst, worst_vertex


class SegmentGrid:
    """The drawing's edges bucketed on a square grid, for nearest-edge queries."""

    def __init__(self, loops):
        self.segs = [(loop[i], loop[(i + 1) % len(loop)]) for loop in loops for i in range(len(loop))]
        xs = [p[0] for loop in loops for p in loop]
        ys = [p[1] for loop in loops for p in loop]
        self.x0, self.y0 = min(xs), min(ys)
        lengths = sorted(math.dist(a, b) for a, b in self.segs)
        span = max(max(xs) - self.x0, max(ys) - self.y0, 1e-300)
        self.h = max(lengths[len(lengths) // 2] * 2, span / 4096, 1e-300)
        self.cells = {}
        for i, (a, b) in enumerate(self.segs):
            for cx in range(self.cell(min(a[0], b[0]), self.x0), self.cell(max(a[0], b[0]), self.x0) + 1):
                for cy in range(self.cell(min(a[1], b[1]), self.y0), self.cell(max(a[1], b[1]), self.y0) + 1):
                    self.cells.setdefault((cx, cy), []).append(i)
        self.reach = int(span / self.h) + 2

    def cell(self, v, v0):
        return int(math.floor((v - v0) / self.h))

    def distance(self, x, y):
        cx, cy = self.cell(x, self.x0), self.cell(y, self.y0)
        best = math.inf
        for ring in range(self.reach + 1):
            for i in range(cx - ring, cx + ring + 1):
                for j in range(cy - ring, cy + ring + 1):
                    if max(abs(i - cx), abs(j - cy)) != ring:
                        continue
                    for s in self.cells.get((i, j), ()):
                        (ax, ay), (bx, by) = self.segs[s]
                        best = min(best, segment_distance(x, y, ax, ay, bx, by))
            if best <= ring * self.h:  # every unvisited cell is farther than ring·h
                break
        return best


def true_to_contour(loops, pieces):
    grid = SegmentGrid(loops)
    edges = sum(len(loop) for loop in loops)
    total = sum(p.length() for p in pieces)
    worst = 0.0
    for p in pieces:
        n = max(64, int(EDGE_SAMPLES * edges * p.length() / total))
        for x, y in p.samples(n):
            worst = max(worst, grid.distance(x, y))
    return worst


def measure(kerf, case, tol, runs, workdir):
    name, scene, plane, size, exact, pieces = case
    out = os.path.join(workdir, "section.dxf")
    times = []
    for _ in range(runs):
        cmd = [kerf, "slice", os.path.join(SCENES, scene), *plane, "-o", out,
               "--tolerance", repr(tol), "--stats"]
        run = subprocess.run(cmd, capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit(f"{' '.join(cmd)}: exit {run.returncode}\n{run.stderr}")
        slice_ms, absolute, kerf_area = parse_stats(run.stderr)
        times.append(slice_ms)
    abs_tol = tol * size
    if abs(absolute - abs_tol) > 5e-3 * abs_tol:
        sys.exit(f"{scene}: kerf's absolute tolerance {absolute} is not {tol} x {size}")
    loops = read_dxf_loops(out)
    area = math.fsum(shoelace(loop) for loop in loops)
    h_fwd, h_vertex = contour_to_true(loops, pieces)
    h_back = true_to_contour(loops, pieces)
    return dict(case=name, tol=tol, abs_tol=abs_tol, loops=len(loops),
                vertices=sum(len(loop) for loop in loops), area=area, kerf_area=kerf_area,
                area_abs=area - exact, area_rel=(area - exact) / exact, h_fwd=h_fwd,
                h_vertex=h_vertex, h_back=h_back, slice_ms=min(times))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--kerf", default="build/kerf")
    ap.add_argument("--runs", type=int, default=1, help="runs per row; the least slice time is kept")
    ap.add_argument("--tolerances", default=",".join(repr(t) for t in TOLERANCES))
    ap.add_argument("--markdown", action="store_true", help="a Markdown table instead of TSV")
    args = ap.parse_args()
    check_ellipse_distance()
    tols = [float(t) for t in args.tolerances.split(",")]
    cols = ["case", "tolerance", "abs tol", "loops", "vertices", "area abs err", "area rel err",
            "H contour→true", "H true→contour", "max H / abs tol", "worst vertex", "slice ms"]
    if args.markdown:
        print("| " + " | ".join(cols) + " |")
        print("|" + "|".join(["---"] + ["---:"] * (len(cols) - 1)) + "|")
    else:
        print("\t".join(cols))
    violations = 0
    with tempfile.TemporaryDirectory() as workdir:
        for case in cases():
            for tol in tols:
                m = measure(args.kerf, case, tol, args.runs, workdir)
                ratio = max(m["h_fwd"], m["h_back"]) / m["abs_tol"]
                violations += ratio > 1
                row = [m["case"], f"{tol:g}", f"{m['abs_tol']:.2g}", str(m["loops"]), str(m["vertices"]),
                       f"{m['area_abs']:+.2e}", f"{m['area_rel']:+.2e}", f"{m['h_fwd']:.2e}",
                       f"{m['h_back']:.2e}", f"{ratio:.3f}" + (" **over**" if ratio > 1 else ""),
                       f"{m['h_vertex']:.1e}", f"{m['slice_ms']:.1f}"]
                print(("| " + " | ".join(row) + " |") if args.markdown else "\t".join(row), flush=True)
                if abs(m["area"] - m["kerf_area"]) > 1e-9 * abs(m["area"]) + 1e-15:
                    print(f"  note: --stats area {m['kerf_area']!r} differs from the DXF's {m['area']!r}",
                          file=sys.stderr)
    if violations:
        print(f"{violations} row(s) with a Hausdorff distance over the tolerance", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
