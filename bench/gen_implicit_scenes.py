#!/usr/bin/env python3
"""Writes the implicit-surface benchmark scenes of issue 8 from one description, so kerf and
POV-Ray read the same numbers (bench/implicit_bench.py renders them):

    bench/scenes/NAME.kerf        for kerf
    bench/scenes/NAME.pov         for POV-Ray 3.7 (isosurface), where POV-Ray takes part
    bench/scenes/NAME.mask.kerf   the same object without the floor, for the coverage check
    bench/scenes/NAME.mask.pov    (POV-Ray renders it with +UA: alpha is its coverage)

Scenes:
  gyroid  gyroid of period 1 (sin 2πx cos 2πy + sin 2πy cos 2πz + sin 2πz cos 2πx <= 0)
          intersected with a sphere of radius 3, on a floor; 800 x 600.
  barth   Barth's sextic clipped by a sphere of radius 1.8, no floor (primary rays and
          shadows); 512 x 512. With f = 4(φ²x²−y²)(φ²y²−z²)(φ²z²−x²) − (1+2φ)(x²+y²+z²−1)² the
          solid is −f <= 0: with f <= 0 the clipping sphere is inside almost everywhere and the
          picture is a ball, with −f <= 0 it is the usual star of cones meeting at the nodes.
  blobs   a union of 10,000 small implicit blobs |q|² − r² + A sin(Kq_x) sin(Kq_y) sin(Kq_z) <= 0
          (q = p − c), each with its own tight bound box, spread in a volume, on a floor.
          kerf only.

In POV-Ray the clipped implicits are `isosurface { function {…} contained_by { sphere } }`,
which keeps the container's surface where the function is inside: the same solid as kerf's
intersection with the sphere. Its max_gradient is `MaxGradient`, declared in the file with the
value that leaves no holes and overridable from the command line (`Declare=MaxGradient=1.1`).
Camera conventions are those of bench/gen_scenes.py (docs/BENCHMARKS.md).

    bench/gen_implicit_scenes.py [--out DIR]     (default: bench/scenes next to this script)
"""
import argparse
import math
import os
import random
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from gen_scenes import Csg, HalfSpace, Material, Scene, Sphere, Transformed, num, vec  # noqa: E402

PHI = (1 + math.sqrt(5)) / 2
FLOOR = HalfSpace((0, 1, 0), 0)


class ClippedImplicit:
    """f <= 0 inside a sphere at the origin: kerf's intersection { implicit sphere }, POV-Ray's
    isosurface contained by the same sphere. kerf_f and pov_f are the same real function."""

    def __init__(self, kerf_f, pov_f, radius):
        self.kerf_f, self.pov_f, self.radius = kerf_f, pov_f, radius

    def kerf(self):
        r = num(self.radius)
        return ("intersection {\n    implicit {\n        f %s\n"
                "        bound box { min <-%s, -%s, -%s> max <%s, %s, %s> }\n    }\n"
                "    sphere { radius %s }\n}" % (self.kerf_f, r, r, r, r, r, r, r))

    def pov(self):
        return ("isosurface {\n    function { %s }\n    contained_by { sphere { 0, %s } }\n"
                "    max_gradient MaxGradient\n}" % (self.pov_f, num(self.radius)))


class Blob:
    """|q|² − r² + A sin(Kq_x) sin(Kq_y) sin(Kq_z) <= 0 around the origin, translated to its
    centre. |bumps| <= A, so the solid lies in the ball of radius sqrt(r² + A): that ball's box
    is the bound. kerf only."""

    def __init__(self, center, radius, amplitude, wavenumber):
        self.center, self.radius = center, radius
        self.amplitude, self.wavenumber = amplitude, wavenumber

    def kerf(self):
        b = math.ceil(math.sqrt(self.radius ** 2 + self.amplitude) * 1e4) / 1e4
        k = num(self.wavenumber)
        return ("implicit { f x^2 + y^2 + z^2 - %s + %s*sin(%s*x)*sin(%s*y)*sin(%s*z) "
                "bound box { min <-%s, -%s, -%s> max <%s, %s, %s> } } translate %s" % (
                    num(round(self.radius ** 2, 10)), num(self.amplitude), k, k, k,
                    *[num(b)] * 6, vec(self.center)))


def gyroid_solid():
    terms = [("x", "y"), ("y", "z"), ("z", "x")]
    kerf_f = " + ".join("sin(2*pi*%s)*cos(2*pi*%s)" % t for t in terms)
    return ClippedImplicit(kerf_f, kerf_f, 3)


def barth_solid():
    p2, c = num(round(PHI * PHI, 15)), num(round(1 + 2 * PHI, 15))
    pairs = [("x", "y"), ("y", "z"), ("z", "x")]
    kerf_f = "%s*(x^2 + y^2 + z^2 - 1)^2 - 4*%s" % (
        c, "*".join("(%s*%s^2 - %s^2)" % (p2, a, b) for a, b in pairs))
    pov_f = "%s*(x*x + y*y + z*z - 1)*(x*x + y*y + z*z - 1) - 4*%s" % (
        c, "*".join("(%s*%s*%s - %s*%s)" % (p2, a, a, b, b) for a, b in pairs))
    return ClippedImplicit(kerf_f, pov_f, 1.8)


def blob_list(count, seed=8):
    """Blobs of radius 0.05-0.09 with centres uniform in a 6 x 3 x 6 slab above the floor;
    bumps of a quarter of r² and about one and a half waves per radius. Rounded to 4 decimals."""
    rng = random.Random(seed)
    blobs = []
    for _ in range(count):
        r = round(rng.uniform(0.05, 0.09), 4)
        centre = (round(rng.uniform(-3, 3), 4), round(rng.uniform(0.15, 3.15), 4),
                  round(rng.uniform(-3, 3), 4))
        blobs.append(Blob(centre, r, round(0.25 * r * r, 8), round(3 * math.pi / r, 4)))
    return blobs


def gyroid_scene(floor):
    scene = Scene(["gyroid: gyroid of period 1 intersected with a sphere of radius 3, on a floor",
                   "(issue 8)."],
                  camera=((0, 5, -12), (0, 3, 0), (0, 1, 0), 35),
                  light=((5, 12, -8), (1, 1, 1), 800), background=(0.1, 0.1, 0.15))
    scene.pov_prelude = ["#ifndef (MaxGradient) #declare MaxGradient = 11; #end"]
    scene.materials.append(Material("clay", (0.8, 0.5, 0.3), 0.1, 0.8))
    scene.objects.append((Transformed(gyroid_solid(), [("translate", (0, 3, 0))]), "clay"))
    if floor:
        scene.objects.append((FLOOR, "clay"))
    return scene


def barth_scene(floor):
    del floor  # no floor in either variant: the scene is the sextic alone
    scene = Scene(["barth: Barth's sextic (phi the golden ratio) clipped by a sphere of radius 1.8",
                   "(issue 8); primary rays and shadows."],
                  camera=((2.2, 3.0, -6.2), (0, 0, 0), (0, 1, 0), 36),
                  light=((6, 9, -7), (1, 1, 1), 900), background=(0.1, 0.1, 0.15),
                  size=(512, 512))
    scene.pov_prelude = ["#ifndef (MaxGradient) #declare MaxGradient = 400; #end"]
    scene.materials.append(Material("gold", (0.9, 0.7, 0.3), 0.1, 0.8))
    scene.objects.append((barth_solid(), "gold"))
    return scene


def blobs_scene(floor):
    scene = Scene(["blobs: a union of 10,000 small bumpy implicit blobs, each with its own tight",
                   "bound box, on a floor (issue 8; kerf only)."],
                  camera=((0, 6, -10), (0, 1.5, 0), (0, 1, 0), 40),
                  light=((5, 12, -8), (1, 1, 1), 900), background=(0.1, 0.1, 0.15))
    scene.materials.append(Material("teal", (0.2, 0.6, 0.6), 0.1, 0.8))
    scene.objects.append((Csg("union", blob_list(10000)), "teal"))
    if floor:
        scene.objects.append((FLOOR, "teal"))
    return scene


# name -> (scene builder, written for POV-Ray too)
SCENES = {"gyroid": (gyroid_scene, True), "barth": (barth_scene, True),
          "blobs": (blobs_scene, False)}


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--out", default=os.path.join(here, "scenes"), help="output folder")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    for name, (make, with_pov) in SCENES.items():
        scene, mask = make(True), make(False)
        files = {name + ".kerf": scene.kerf()}
        if len(mask.objects) < len(scene.objects):  # else the scene itself serves as the mask
            files[name + ".mask.kerf"] = mask.kerf()
        if with_pov:
            files[name + ".pov"] = scene.pov()
            # POV-Ray's background becomes transparent under +UA only with transmit 1.
            files[name + ".mask.pov"] = mask.pov().replace(
                "background { color rgb %s }" % vec(mask.background),
                "background { color rgbt <0, 0, 0, 1> }")
        for file_name, text in files.items():
            with open(os.path.join(args.out, file_name), "w", encoding="utf-8") as out:
                out.write(text.replace("bench/gen_scenes.py", "bench/gen_implicit_scenes.py"))
    print("wrote %d implicit scenes into %s" % (len(SCENES), args.out))


if __name__ == "__main__":
    main()
