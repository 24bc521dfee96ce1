#!/usr/bin/env python3
"""The three meshes of the Embree comparison (issue 12 §3, docs/BENCHMARKS.md "Meshes against
Embree"), written as binary little-endian PLY files into a folder:

  sphere.ply  a bumpy sphere: a latitude-longitude grid of 500 x 1000 quads with a displaced
              radius, 998,000 triangles (the same surface as bench/bvh_bench.cpp's)
  city.ply    10,000 boxes of random size and height on a 100 x 100 ground, 120,000 triangles
  fan.ply     100,000 long thin triangles from a shared centre to a unit circle

Coordinates are stored as 32-bit floats, so kerf (double) and Embree (float) trace exactly the
same triangles. Deterministic: the city's boxes come from a seeded generator. Plain Python
(no numpy needed); all three take about 10 s.

  python3 bench/gen_bench_meshes.py OUTDIR
"""
import argparse
import math
import os
import random
import struct
import sys
from array import array


def write_ply(path, positions, triangles):
    """positions: flat list of x, y, z; triangles: flat list of i, j, k. Written to a temporary
    file and renamed, so a reader never sees half a mesh."""
    vertices = array("f", positions)
    if sys.byteorder != "little":
        vertices.byteswap()
    # Each face is a list of 3 (uchar) followed by 3 int32 indices.
    face = struct.Struct("<B3i")
    faces = bytearray(face.size * (len(triangles) // 3))
    for n in range(len(triangles) // 3):
        face.pack_into(faces, n * face.size, 3, triangles[3 * n], triangles[3 * n + 1],
                       triangles[3 * n + 2])
    header = ("ply\nformat binary_little_endian 1.0\n"
              f"element vertex {len(positions) // 3}\n"
              "property float x\nproperty float y\nproperty float z\n"
              f"element face {len(triangles) // 3}\n"
              "property list uchar int vertex_indices\nend_header\n")
    tmp = path + ".tmp"
    with open(tmp, "wb") as f:
        f.write(header.encode("ascii"))
        f.write(vertices.tobytes())
        f.write(faces)
    os.replace(tmp, path)


def bumpy_sphere(rows=500, cols=1000):
    """Radius 1 with two bands of bumps (4% and 1%); poles closed by triangle fans."""
    def radius(th, ph):
        return (1.0 + 0.04 * math.sin(17.0 * th) * math.sin(23.0 * ph) +
                0.01 * math.sin(91.0 * th + 3.0) * math.cos(77.0 * ph))
    p = [0.0, 0.0, radius(0.0, 0.0)]
    for i in range(1, rows):
        th = math.pi * i / rows
        st, ct = math.sin(th), math.cos(th)
        for j in range(cols):
            ph = 2.0 * math.pi * j / cols
            r = radius(th, ph)
            p += (r * st * math.cos(ph), r * st * math.sin(ph), r * ct)
    p += (0.0, 0.0, -radius(math.pi, 0.0))
    south = len(p) // 3 - 1

    def v(i, j):
        return 1 + (i - 1) * cols + j % cols
    t = []
    for j in range(cols):
        t += (0, v(1, j), v(1, j + 1))
        t += (south, v(rows - 1, j + 1), v(rows - 1, j))
    for i in range(1, rows - 1):
        for j in range(cols):
            a, b, c, d = v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)
            t += (a, b, c, a, c, d)
    return p, t


def city(boxes=10000, seed=1):
    """Boxes with corners uniform on [-50, 50]^2, sides 0.3-2 and heights 1-15 (most low)."""
    rng = random.Random(seed)
    quads = ((0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5))
    p, t = [], []
    for _ in range(boxes):
        lo = (rng.uniform(-50.0, 50.0), rng.uniform(-50.0, 50.0), 0.0)
        hi = (lo[0] + rng.uniform(0.3, 2.0), lo[1] + rng.uniform(0.3, 2.0),
              1.0 + 14.0 * rng.random() ** 3)
        k = len(p) // 3
        for c in range(8):
            p += (hi[0] if c & 1 else lo[0], hi[1] if c & 2 else lo[1], hi[2] if c & 4 else lo[2])
        for q in quads:  # outward, counter-clockwise seen from outside
            t += (k + q[0], k + q[1], k + q[2], k + q[0], k + q[2], k + q[3])
    return p, t


def fan(n=100000):
    """n triangles from the origin to consecutive points of the unit circle (plane z = 0)."""
    p = [0.0, 0.0, 0.0]
    for i in range(n):
        a = 2.0 * math.pi * i / n
        p += (math.cos(a), math.sin(a), 0.0)
    t = []
    for i in range(n):
        t += (0, 1 + i, 1 + (i + 1) % n)
    return p, t


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("outdir", help="folder to write sphere.ply, city.ply and fan.ply into")
    args = ap.parse_args()
    try:
        os.makedirs(args.outdir, exist_ok=True)
    except OSError as e:
        print(f"gen_bench_meshes.py: {args.outdir}: {e.strerror}", file=sys.stderr)
        return 2
    for name, make in (("sphere", bumpy_sphere), ("city", city), ("fan", fan)):
        p, t = make()
        write_ply(os.path.join(args.outdir, name + ".ply"), p, t)
        print(f"{name}.ply: {len(p) // 3} vertices, {len(t) // 3} triangles")
    return 0


if __name__ == "__main__":
    sys.exit(main())
