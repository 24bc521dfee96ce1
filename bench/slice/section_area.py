#!/usr/bin/env python3
"""The area of a section file (SVG paths or DXF LINE / LWPOLYLINE entities), standard library only.

Loops are read whatever their orientation and combined by the even-odd rule: a loop nested in
an odd number of others is a hole. Each loop's area is the shoelace sum taken about its first
vertex (math.fsum), so large coordinates lose no digits. Used by bench/slice/slice_bench.py on
kerf's and OpenSCAD's outputs alike.

    python3 bench/slice/section_area.py FILE.svg|FILE.dxf    # prints the area and the loop count
"""
import math
import re
import sys

NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


def svg_loops(text):
    """Closed subpaths of every <path d="…"> (M/L/H/V/Z, absolute or relative)."""
    loops = []
    for d in re.findall(r'\sd="([^"]*)"', text):
        tokens = re.findall(r"[MmLlHhVvZz]|" + NUMBER, d)
        loop, x, y, command, k = [], 0.0, 0.0, "M", 0
        while k < len(tokens):
            t = tokens[k]
            if t in "MmLlHhVvZz":
                command = t
                k += 1
                if t in "Zz":
                    if loop:
                        loops.append(loop)
                        x, y = loop[0]
                    loop = []
                continue
            if command in "Mm":
                if loop:
                    loops.append(loop)
                dx, dy = float(tokens[k]), float(tokens[k + 1])
                x, y = (x + dx, y + dy) if command == "m" else (dx, dy)
                loop = [(x, y)]
                command = "l" if command == "m" else "L"  # implicit lineto after a moveto
                k += 2
            elif command in "Ll":
                dx, dy = float(tokens[k]), float(tokens[k + 1])
                x, y = (x + dx, y + dy) if command == "l" else (dx, dy)
                loop.append((x, y))
                k += 2
            elif command in "Hh":
                x = x + float(tokens[k]) if command == "h" else float(tokens[k])
                loop.append((x, y))
                k += 1
            else:  # V v
                y = y + float(tokens[k]) if command == "v" else float(tokens[k])
                loop.append((x, y))
                k += 1
        if loop:
            loops.append(loop)
    return loops


def dxf_loops(text):
    """LWPOLYLINE entities as loops, and LINE entities chained end to start into loops."""
    lines = text.splitlines()
    pairs = [(int(lines[k].strip()), lines[k + 1].strip()) for k in range(0, len(lines) - 1, 2)]
    loops, segments = [], []
    k = 0
    while k < len(pairs):
        code, value = pairs[k]
        if code == 0 and value in ("LWPOLYLINE", "LINE"):
            fields, m = [], k + 1
            while m < len(pairs) and pairs[m][0] != 0:
                fields.append(pairs[m])
                m += 1
            if value == "LWPOLYLINE":
                loop = []
                for c, v in fields:
                    if c == 10:
                        loop.append([float(v), 0.0])
                    elif c == 20:
                        loop[-1][1] = float(v)
                loops.append([tuple(p) for p in loop])
            else:
                f = dict(fields)
                segments.append(((f[10], f[20]), (f[11], f[21])))
            k = m
        else:
            k += 1
    # Chain the LINEs: each start point is the end of exactly one other segment.
    by_start = {}
    for a, b in segments:
        by_start.setdefault(a, []).append(b)
    while by_start:
        start = next(iter(by_start))
        loop, point = [], start
        while point in by_start:
            loop.append((float(point[0]), float(point[1])))
            ends = by_start[point]
            nxt = ends.pop()
            if not ends:
                del by_start[point]
            point = nxt
        loops.append(loop)
    return loops


def loop_area(loop):
    x0, y0 = loop[0]
    n = len(loop)
    return 0.5 * math.fsum((loop[i][0] - x0) * (loop[(i + 1) % n][1] - y0) -
                           (loop[(i + 1) % n][0] - x0) * (loop[i][1] - y0) for i in range(n))


def inside(point, loop):
    """Even-odd point in polygon (the point is never on the loop: loops do not touch)."""
    x, y = point
    c = False
    n = len(loop)
    for i in range(n):
        (x1, y1), (x2, y2) = loop[i], loop[(i + 1) % n]
        if (y1 > y) != (y2 > y) and x < x1 + (y - y1) * (x2 - x1) / (y2 - y1):
            c = not c
    return c


def section_area(loops):
    loops = [l for l in loops if len(l) >= 3]
    boxes = [(min(p[0] for p in l), max(p[0] for p in l), min(p[1] for p in l), max(p[1] for p in l))
             for l in loops]
    total = []
    for i, loop in enumerate(loops):
        p = loop[0]
        depth = sum(1 for j, other in enumerate(loops)
                    if j != i and boxes[j][0] <= p[0] <= boxes[j][1] and boxes[j][2] <= p[1] <= boxes[j][3]
                    and inside(p, other))
        total.append((-1) ** depth * abs(loop_area(loop)))
    return math.fsum(total), len(loops)


def file_area(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        text = f.read()
    return section_area(dxf_loops(text) if path.lower().endswith(".dxf") else svg_loops(text))


if __name__ == "__main__":
    area, count = file_area(sys.argv[1])
    print(f"{area!r} {count}")
