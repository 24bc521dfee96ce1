#!/usr/bin/env python3
"""Writes every benchmark scene three times from one description, so the peers render the same
geometry and the depth oracle checks the same surfaces:

    bench/scenes/NAME.kerf   for kerf
    bench/scenes/NAME.pov    for POV-Ray 3.7
    bench/scenes/NAME.ref    for bench/depth_reference (a line-based, prefix-order scene list)

Scenes: cup (the issue's cup without the gyroid, the lamp, the directional light and the mist),
box_minus_spheres_N for N in 10, 100, 1000, 5000 (a box with N spheres subtracted near its faces;
the first k spheres are the same for every N >= k), tori (six tori of different radii).
Every scene has one point light with shadows, ambient light, and a floor.

Handedness: kerf is right-handed with y up; POV-Ray is left-handed. The .pov files keep every
coordinate as it is and make POV-Ray's camera right-handed with `right -x*image_width/image_height`
(POV-Ray keeps the handedness of right/up/direction when it applies look_at). POV-Ray's `rotate`
uses the same matrices as kerf's (x' = x cos + z sin for a y rotation, and so on), so rotations
carry over unchanged. POV-Ray's `angle` is the horizontal field of view: the .pov computes it from
kerf's vertical fov and the image's aspect ratio.

    bench/gen_scenes.py [--out DIR]     (default: bench/scenes next to this script)
"""
import argparse
import math
import os
import random


def vec(v):
    return "<%s>" % ", ".join(num(c) for c in v)


def num(x):
    return repr(float(x)) if x != int(x) else str(int(x))


def pov_camera_lines(max_depth, eye, fov, up=None):
    """POV-Ray's global settings and the opening of a camera matching kerf's: vertical fov,
    right-handed (right -x). The caller adds look_at (and any lens) and the closing brace."""
    lines = ["global_settings { assumed_gamma 1.0 max_trace_level %d ambient_light rgb 1 }"
             % max_depth,
             "camera {",
             "    perspective",
             "    location %s" % vec(eye),
             "    up y",
             "    right -x*image_width/image_height",
             "    angle 2*degrees(atan(tan(radians(%s)/2)*image_width/image_height))" % num(fov)]
    if up is not None:
        lines.append("    sky %s" % vec(up))
    return lines


def indent(texts):
    return "\n".join("    " + line for text in texts for line in text.split("\n"))


def ref_nums(v):
    return " ".join(num(c) for c in v)


# ---------------------------------------------------------------------------------------------
# Solids: each writes itself as kerf, POV-Ray SDL and oracle text.

class Sphere:
    def __init__(self, center, radius):
        self.center, self.radius = center, radius

    def kerf(self):
        return "sphere { center %s radius %s }" % (vec(self.center), num(self.radius))

    def pov(self):
        return "sphere { %s, %s }" % (vec(self.center), num(self.radius))

    def ref(self):
        return ["sphere %s %s" % (ref_nums(self.center), num(self.radius))]


class Box:
    def __init__(self, lo, hi):
        self.lo, self.hi = lo, hi

    def kerf(self):
        return "box { min %s max %s }" % (vec(self.lo), vec(self.hi))

    def pov(self):
        return "box { %s, %s }" % (vec(self.lo), vec(self.hi))

    def ref(self):
        return ["box %s %s" % (ref_nums(self.lo), ref_nums(self.hi))]


class Cylinder:
    def __init__(self, a, b, radius):
        self.a, self.b, self.radius = a, b, radius

    def kerf(self):
        return "cylinder { from %s to %s radius %s }" % (vec(self.a), vec(self.b), num(self.radius))

    def pov(self):
        return "cylinder { %s, %s, %s }" % (vec(self.a), vec(self.b), num(self.radius))

    def ref(self):
        return ["cylinder %s %s %s" % (ref_nums(self.a), ref_nums(self.b), num(self.radius))]


class HalfSpace:
    """All p with normal . p <= offset: POV-Ray's plane has the same inside."""

    def __init__(self, normal, offset):
        self.normal, self.offset = normal, offset

    def kerf(self):
        return "halfspace { normal %s offset %s }" % (vec(self.normal), num(self.offset))

    def pov(self):
        return "plane { %s, %s }" % (vec(self.normal), num(self.offset))

    def ref(self):
        return ["halfspace %s %s" % (ref_nums(self.normal), num(self.offset))]


class Torus:
    """Around the y axis, centred at the origin, in kerf and in POV-Ray alike."""

    def __init__(self, major, minor):
        self.major, self.minor = major, minor

    def kerf(self):
        return "torus { major %s minor %s }" % (num(self.major), num(self.minor))

    def pov(self):
        return "torus { %s, %s }" % (num(self.major), num(self.minor))

    def ref(self):
        return ["torus %s %s" % (num(self.major), num(self.minor))]


class Csg:
    """union | intersection | difference (the first minus all the rest)."""

    def __init__(self, op, children):
        self.op, self.children = op, children

    def kerf(self):
        return "%s {\n%s\n}" % (self.op, indent(c.kerf() for c in self.children))

    def pov(self):
        return "%s {\n%s\n}" % (self.op, indent(c.pov() for c in self.children))

    def ref(self):
        lines = ["%s %d" % (self.op, len(self.children))]
        for c in self.children:
            lines += c.ref()
        return lines


class Named:
    """A named solid: `solid NAME = ...;` in kerf, `#declare NAME = ...;` in POV-Ray."""

    def __init__(self, name, solid):
        self.name, self.solid = name, solid

    def kerf(self):
        return self.name

    def pov(self):
        return "object { %s }" % self.name

    def ref(self):
        return self.solid.ref()


class Transformed:
    """A solid followed by modifiers applied left to right: ("translate"|"rotate"|"scale", v)."""

    def __init__(self, solid, modifiers):
        self.solid, self.modifiers = solid, modifiers

    def kerf(self):
        return self.solid.kerf() + split_modifiers(self)[1]

    def pov(self):
        return "object { %s%s }" % (self.solid.pov(), split_modifiers(self)[1])

    def ref(self):
        # The oracle reads one node per modifier, outermost first: the last modifier wraps all.
        lines = []
        for k, v in reversed(self.modifiers):
            lines.append("%s %s" % (k, ref_nums(v)))
        return lines + self.solid.ref()


# ---------------------------------------------------------------------------------------------
# Materials and scene assembly.

class Material:
    def __init__(self, name, color, ambient=0.1, diffuse=0.8, specular=0.0, shininess=20,
                 reflect=0.0):
        self.name, self.color = name, color
        self.ambient, self.diffuse = ambient, diffuse
        self.specular, self.shininess, self.reflect = specular, shininess, reflect

    def kerf(self):
        text = "material %s { color %s ambient %s diffuse %s" % (
            self.name, vec(self.color), num(self.ambient), num(self.diffuse))
        if self.specular:
            text += " specular %s shininess %s" % (num(self.specular), num(self.shininess))
        if self.reflect:
            text += " reflect %s" % num(self.reflect)
        return text + " }"

    def pov(self):
        finish = "ambient %s diffuse %s" % (num(self.ambient), num(self.diffuse))
        if self.specular:
            finish += " phong %s phong_size %s" % (num(self.specular), num(self.shininess))
        if self.reflect:
            finish += " reflection { %s }" % num(self.reflect)
        return "#declare %s = texture { pigment { color rgb %s } finish { %s } };" % (
            self.name.capitalize(), vec(self.color), finish)


class Scene:
    def __init__(self, title, camera, light, background, max_depth=4, size=(800, 600)):
        self.title = title
        self.size = size      # the render block's width and height (the harness passes them too)
        self.pov_prelude = []  # lines right after #version (e.g. #ifndef defaults)
        self.camera = camera  # (eye, look_at, up, vertical fov in degrees)
        self.light = light    # (position, colour, kerf power)
        self.background = background
        self.max_depth = max_depth
        self.named, self.materials, self.objects = [], [], []

    def kerf(self):
        eye, look_at, up, fov = self.camera
        at, color, power = self.light
        out = ["// %s" % line for line in self.title]
        out += ["// GENERATED by bench/gen_scenes.py: edit the script, not this file.", ""]
        out += ["solid %s = %s;" % (n.name, n.solid.kerf()) for n in self.named]
        out += [m.kerf() for m in self.materials]
        # kerf puts the material right after the solid, before the modifiers.
        for solid, material in self.objects:
            inner, mods = split_modifiers(solid)
            out.append("object %s material %s%s;" % (inner.kerf(), material, mods))
        out += [
            "camera { eye %s look_at %s up %s fov %s }" % (vec(eye), vec(look_at), vec(up),
                                                             num(fov)),
            "light point { at %s color %s power %s }" % (vec(at), vec(color), num(power)),
            "background %s;" % vec(self.background),
            "render { width %d height %d spp 1 max_depth %d }" % (*self.size, self.max_depth),
            "",
        ]
        return "\n".join(out)

    def pov(self):
        eye, look_at, up, fov = self.camera
        at, color, _ = self.light
        out = ["// %s" % line for line in self.title]
        out += [
            "// GENERATED by bench/gen_scenes.py: edit the script, not this file.",
            "// Same geometry as the .kerf beside it; the camera is made right-handed (right -x).",
            "#version 3.7;",
            *self.pov_prelude,
            *pov_camera_lines(self.max_depth, eye, fov, up),
            "    look_at %s" % vec(look_at),
            "}",
            "light_source { %s color rgb %s }" % (vec(at), vec(color)),
            "background { color rgb %s }" % vec(self.background),
        ]
        out += [m.pov() for m in self.materials]
        out += ["#declare %s = %s;" % (n.name, n.solid.pov()) for n in self.named]
        for solid, material in self.objects:
            inner, mods = split_modifiers(solid)
            out.append("object { %s texture { %s }%s }" % (inner.pov(), material.capitalize(),
                                                           mods))
        return "\n".join(out) + "\n"

    def ref(self):
        eye, look_at, up, fov = self.camera
        out = ["# GENERATED by bench/gen_scenes.py for bench/depth_reference: the same surfaces",
               "# as the .kerf beside it. One node per line, children after their parent.",
               "camera %s %s %s %s" % (ref_nums(eye), ref_nums(look_at), ref_nums(up), num(fov))]
        for solid, _ in self.objects:
            out.append("object")
            out += solid.ref()
        return "\n".join(out) + "\n"


def split_modifiers(solid):
    """(the solid without its top-level modifiers, those modifiers as text): the same text in
    kerf and in POV-Ray."""
    if isinstance(solid, Transformed):
        return solid.solid, "".join(" %s %s" % (k, vec(v)) for k, v in solid.modifiers)
    return solid, ""


FLOOR = HalfSpace((0, 1, 0), 0)


def cup_scene():
    radius = 1.2
    wall = radius / 10
    body = Csg("difference", [
        Cylinder((0, 0, 0), (0, 2.4, 0), radius),
        Cylinder((0, wall, 0), (0, 2.5, 0), radius - wall),
    ])
    handle = Transformed(Csg("difference", [
        Cylinder((0, 0, -0.1), (0, 0, 0.1), 0.7),
        Cylinder((0, 0, -0.2), (0, 0, 0.2), 0.5),
        HalfSpace((1, 0, 0), 0),
    ]), [("translate", (radius - 0.05, 1.2, 0))])
    cup = Named("cup", Csg("union", [body, handle]))
    scene = Scene(["cup: the issue's example without the gyroid, the lamp, the directional light",
                   "and the mist (POV-Ray's isosurface gyroid is a different benchmark)."],
                  camera=((0, 3, -9), (0, 1, 0), (0, 1, 0), 35),
                  light=((5, 8, -5), (1, 1, 1), 300), background=(0.1, 0.1, 0.15))
    scene.named.append(cup)
    scene.materials += [
        Material("clay", (0.8, 0.5, 0.3), 0.1, 0.8, 0.3, 20),
        Material("mirror", (0.9, 0.9, 0.9), 0.1, 0.8, 0.5, 80, reflect=0.85),
    ]
    scene.objects += [
        (Transformed(cup, [("rotate", (0, 30, 0))]), "clay"),
        (Transformed(cup, [("translate", (-3, 0, 0))]), "mirror"),
        (FLOOR, "clay"),
    ]
    return scene


BOX_MIN, BOX_MAX = (-2.0, 0.0, -2.0), (2.0, 2.0, 2.0)


def sphere_list(count, seed=1):
    """Spheres of radius 0.08 to 0.15 whose centres lie within 0.6 r inside to 0.5 r outside a
    face of the box (faces chosen by area), so each one cuts the box. Rounded to 4 decimals so
    the three files carry exactly the same numbers."""
    rng = random.Random(seed)
    size = [BOX_MAX[i] - BOX_MIN[i] for i in range(3)]
    faces, weights = [], []
    for axis in range(3):
        u, v = [a for a in range(3) if a != axis]
        for side in (-1, 1):
            faces.append((axis, side))
            weights.append(size[u] * size[v])
    spheres = []
    for _ in range(count):
        axis, side = rng.choices(faces, weights=weights)[0]
        radius = rng.uniform(0.08, 0.15)
        centre = [rng.uniform(BOX_MIN[i], BOX_MAX[i]) for i in range(3)]
        plane = BOX_MAX[axis] if side > 0 else BOX_MIN[axis]
        centre[axis] = plane + side * rng.uniform(-0.6 * radius, 0.5 * radius)
        spheres.append(Sphere(tuple(round(c, 4) for c in centre), round(radius, 4)))
    return spheres


def box_minus_spheres_scene(count):
    block = Csg("difference", [Box(BOX_MIN, BOX_MAX)] + sphere_list(count))
    scene = Scene(["box_minus_spheres_%d: a 4 x 2 x 4 box with %d spheres subtracted near its "
                   "faces, on a floor." % (count, count)],
                  camera=((5.5, 5, -7.5), (0, 0.8, 0), (0, 1, 0), 38),
                  light=((6, 10, -4), (1, 0.97, 0.92), 1400), background=(0.55, 0.65, 0.8))
    scene.materials += [
        Material("stone", (0.85, 0.62, 0.42), 0.12, 0.75, 0.25, 30),
        Material("ground", (0.55, 0.58, 0.62), 0.1, 0.8),
    ]
    scene.objects += [(block, "stone"), (FLOOR, "ground")]
    return scene


def tori_scene():
    def torus(major, minor, modifiers):
        return Transformed(Torus(major, minor), modifiers)

    scene = Scene(["tori: six tori of different major and minor radii, lying, standing and tilted,",
                   "on a floor."],
                  camera=((0, 4.5, -9), (0, 0.8, 0.5), (0, 1, 0), 40),
                  light=((4, 9, -6), (1, 1, 1), 500), background=(0.2, 0.22, 0.3))
    scene.materials += [
        Material("gold", (0.9, 0.7, 0.3), 0.1, 0.7, 0.6, 60),
        Material("teal", (0.2, 0.6, 0.6), 0.1, 0.8, 0.3, 20),
        Material("ground", (0.6, 0.6, 0.6), 0.1, 0.8),
    ]
    scene.objects += [
        (torus(1.0, 0.3, [("translate", (-2.6, 0.3, 0))]), "gold"),
        (torus(0.8, 0.15, [("rotate", (90, 0, 0)), ("translate", (0, 0.95, -0.5))]), "teal"),
        (torus(0.6, 0.45, [("translate", (2.5, 0.45, 0.2))]), "gold"),
        (torus(1.6, 0.06, [("rotate", (70, 0, 25)), ("translate", (0.2, 1.7, 2.6))]), "teal"),
        (torus(0.45, 0.12, [("rotate", (0, 0, 90)), ("rotate", (0, 40, 0)),
                            ("translate", (-1.2, 0.57, -2.2))]), "teal"),
        (torus(1.1, 0.5, [("rotate", (-30, 20, 0)), ("translate", (-2.4, 1.4, 3.2))]), "gold"),
        (FLOOR, "ground"),
    ]
    return scene


def all_scenes():
    scenes = [("cup", cup_scene())]
    scenes += [("box_minus_spheres_%d" % n, box_minus_spheres_scene(n))
               for n in (10, 100, 1000, 5000)]
    scenes.append(("tori", tori_scene()))
    return scenes


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--out", default=os.path.join(here, "scenes"), help="output folder")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    for name, scene in all_scenes():
        for ext, text in (("kerf", scene.kerf()), ("pov", scene.pov()), ("ref", scene.ref())):
            path = os.path.join(args.out, "%s.%s" % (name, ext))
            with open(path, "w", encoding="utf-8") as out:
                out.write(text)
    print("wrote %d scenes into %s" % (len(all_scenes()), args.out))


if __name__ == "__main__":
    main()
