#!/usr/bin/env python3
"""Classifies the pixels where a kerf render and its reference disagree (bench/hit_mask --list
output: "i j test reference", inf = miss): is the reference's nearest span there thinner than
the test render's tolerance? kerf drops such spans by design (docs/architecture.md: spans
thinner than their boundaries' error vanish), so those disagreements are expected; the others
are surfaces the test render missed.

For each pixel the reference hits, it walks the pixel-centre ray (kerf's camera formula) from
the reference's hit through the solid, in steps of 1/64 of tolerance x distance: the span is
thin if the ray is outside again within tolerance x distance, borderline if within twice that
(kerf compares a span with its two boundaries' errors, each up to the tolerance), thick
otherwise, or if the field is not outside just before the hit (the hit is on something this
script does not model). Only the scenes of bench/gen_implicit_scenes.py and the glass gyroid of
models/cup.kerf, whose functions it evaluates in double precision here (checked: at 1000 random reference hits of each scene the function
changes sign across the reference depth +-1e-4 relative).

    bench/thin_spans.py SCENE LIST --width W --height H --tolerance T    (SCENE: gyroid barth blobs cup)
"""
import argparse
import json
import math
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import gen_implicit_scenes as scenes  # noqa: E402


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def norm(a):
    return math.sqrt(sum(x * x for x in a))


def unit(a):
    n = norm(a)
    return tuple(x / n for x in a)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def camera_rays(camera, width, height):
    """rayThrough(i + 0.5, j + 0.5) of render/camera.cpp: (eye, unit direction)."""
    eye, look_at, up, fov = camera
    forward = unit(sub(look_at, eye))
    right = unit(cross(forward, unit(up)))
    true_up = cross(right, forward)
    tan_half = math.tan(0.5 * math.radians(fov))

    def ray(i, j):
        sx = ((i + 0.5) / width * 2 - 1) * tan_half * (width / height)
        sy = (1 - (j + 0.5) / height * 2) * tan_half
        return eye, unit(tuple(f + sx * r + sy * u for f, r, u in zip(forward, right, true_up)))
    return ray


def gyroid_field():
    k = 2 * math.pi

    def f(p):
        x, y, z = p[0], p[1] - 3, p[2]
        g = (math.sin(k * x) * math.cos(k * y) + math.sin(k * y) * math.cos(k * z)
             + math.sin(k * z) * math.cos(k * x))
        return min(max(g, math.sqrt(x * x + y * y + z * z) - 3), p[1])  # ∪ the floor y <= 0
    return f


def barth_field():
    p2, c = scenes.PHI ** 2, 1 + 2 * scenes.PHI

    def f(p):
        x, y, z = p
        r2 = x * x + y * y + z * z
        sextic = c * (r2 - 1) ** 2 - 4 * (p2 * x * x - y * y) * (p2 * y * y - z * z) \
            * (p2 * z * z - x * x)
        return max(sextic, math.sqrt(r2) - 1.8)
    return f


def blobs_field():
    """The union of the blobs near p (a hash grid of their bounding balls) and the floor."""
    cell = 0.25
    grid = {}
    for b in scenes.blob_list(10000):
        reach = math.sqrt(b.radius ** 2 + b.amplitude)
        lo = [math.floor((c - reach) / cell) for c in b.center]
        hi = [math.floor((c + reach) / cell) for c in b.center]
        for i in range(lo[0], hi[0] + 1):
            for j in range(lo[1], hi[1] + 1):
                for k in range(lo[2], hi[2] + 1):
                    grid.setdefault((i, j, k), []).append(b)

    def f(p):
        value = p[1]
        for b in grid.get(tuple(math.floor(c / cell) for c in p), ()):
            q = sub(p, b.center)
            w = b.wavenumber
            blob = (q[0] ** 2 + q[1] ** 2 + q[2] ** 2 - round(b.radius ** 2, 10)
                    + b.amplitude * math.sin(w * q[0]) * math.sin(w * q[1]) * math.sin(w * q[2]))
            value = min(value, blob)
        return value
    return f


def cup_field():
    """Only the glass gyroid of models/cup.kerf (scale 0.8, translate <3, 1, 0>, bound by the
    box [-1, 1]³); a disagreement elsewhere in that model counts as thick."""
    def f(p):
        x, y, z = ((p[0] - 3) / 0.8, (p[1] - 1) / 0.8, p[2] / 0.8)
        g = math.sin(4 * x) * math.cos(4 * y) + math.sin(4 * y) * math.cos(4 * z) \
            + math.sin(4 * z) * math.cos(4 * x)
        return max(g, max(abs(x), abs(y), abs(z)) - 1)
    return f


CUP_CAMERA = ((0, 3, -9), (0, 1, 0), (0, 1, 0), 35)  # models/cup.kerf's camera
FIELDS = {"gyroid": gyroid_field, "barth": barth_field, "blobs": blobs_field, "cup": cup_field}


def scene_camera(scene):
    return CUP_CAMERA if scene == "cup" else scenes.SCENES[scene][0](True).camera


def classify(scene, list_path, width, height, tolerance):
    ray = camera_rays(scene_camera(scene), width, height)
    f = FIELDS[scene]()
    counts = {"pixels": 0, "thin": 0, "borderline": 0, "thick": 0, "reference_miss": 0}
    with open(list_path, encoding="utf-8") as listing:
        for line in listing:
            i, j, _, reference = line.split()
            counts["pixels"] += 1
            depth = float(reference)
            if math.isinf(depth):
                counts["reference_miss"] += 1
                continue
            eye, direction = ray(int(i), int(j))
            step = tolerance * depth / 64
            kind = "thick"
            before = depth - step
            if f(tuple(e + before * d for e, d in zip(eye, direction))) <= 0:
                counts[kind] += 1  # the reference's hit is not where this field enters
                continue
            for n in range(1, 129):
                t = depth + n * step
                if f(tuple(e + t * d for e, d in zip(eye, direction))) > 0:
                    kind = "thin" if n <= 64 else "borderline"
                    break
            counts[kind] += 1
    return counts


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scene", choices=list(FIELDS))
    parser.add_argument("list")
    parser.add_argument("--width", type=int, required=True)
    parser.add_argument("--height", type=int, required=True)
    parser.add_argument("--tolerance", type=float, required=True)
    args = parser.parse_args()
    print(json.dumps(classify(args.scene, args.list, args.width, args.height, args.tolerance)))


if __name__ == "__main__":
    main()
