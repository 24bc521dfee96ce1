#!/usr/bin/env python3
"""Noise against time (issue 10 §4), in one run:

1. Samplers. For noise_shadow, noise_dof and noise_glossy (bench/gen_noise_scenes.py), kerf
   renders each sampler at each spp; the error is the RMSE of the linear EXR against a
   4096-spp jittered kerf reference (every pixel, R, G and B alike). A 1024-spp lattice
   render is compared with the reference too: the RMSE between them bounds how much of the
   error the reference itself contributes. Slopes are least-squares fits of log RMSE against
   log spp.
2. Against POV-Ray 3.7 (noise_shadow, noise_dof). Each renderer is measured against its own
   high-sample reference at several settings; the settings no other setting beats in both
   time and error (the Pareto front) are timed three times more, and the trace time at a
   common RMSE is interpolated along each front, linearly in log time against log RMSE.

Reading EXR files: OpenImageIO's `oiiotool --dumpdata` (no Python bindings or numpy needed).
Writes bench/out/noise/results.json and, unless --quick, the noise section at the end of
docs/BENCHMARKS.md.

    bench/noise_bench.py --kerf build/kerf [--quick] [--runs 3] [--scenes noise_shadow ...]
"""
import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from run_bench import kerf_stats, load_average, pov_stats, run_timed, shown, versions  # noqa

SCENES = ["noise_shadow", "noise_dof", "noise_glossy"]
SAMPLERS = ["random", "jittered", "lattice", "regular"]
SPPS = [4, 16, 64, 256]
KERF_POV_SAMPLERS = ["jittered", "lattice"]
KERF_POV_SPPS = [2, 4, 8, 16, 32, 64, 128, 256]
# kerf's adaptive sampling (render { noise T }: at least 16 and at most 256 spp, jittered),
# the counterpart of POV-Ray's adaptive anti-aliasing.
KERF_NOISE = [0.04, 0.02, 0.01, 0.005]
KERF_CURVES = KERF_POV_SAMPLERS + ["adaptive"]
# POV-Ray settings per scene: (label, extra arguments). Its reference is the last entry of
# POV_REFERENCE.
POV_AA = [("no AA", ["-A"]),
          ("AA 0.05 AM2 R3", ["+A0.05", "+AM2", "+R3", "+J"]),
          ("AA 0 AM1 R2", ["+A0.0", "+AM1", "+R2", "+J"]),
          ("AA 0 AM1 R3", ["+A0.0", "+AM1", "+R3", "+J"]),
          ("AA 0 AM1 R4", ["+A0.0", "+AM1", "+R4", "+J"])]
POV_SETTINGS = {
    "noise_shadow": [("area %d×%d, %s" % (n, n, label), ["Declare=LightN=%d" % n] + aa)
                     for n in (3, 5, 9, 17, 33) for label, aa in POV_AA],
    "noise_dof": [("blur_samples %d" % n, ["Declare=BlurSamples=%d" % n, "-A"])
                  for n in (4, 7, 19, 37, 64, 128, 256)],
}
POV_REFERENCE = {
    "noise_shadow": ("area 65×65, AA 0 AM1 R6",
                     ["Declare=LightN=65", "+A0.0", "+AM1", "+R6", "+J"]),
    "noise_dof": ("blur_samples 2048", ["Declare=BlurSamples=2048", "-A"]),
}
QUICK_POV_REFERENCE = {
    "noise_shadow": ("area 33×33, AA 0 AM1 R4",
                     ["Declare=LightN=33", "+A0.0", "+AM1", "+R4", "+J"]),
    "noise_dof": ("blur_samples 256", ["Declare=BlurSamples=256", "-A"]),
}
# The check of POV-Ray's reference: the scene at twice the width and height, averaged over
# 2 x 2 pixels, so every sample lies elsewhere (POV-Ray's jitter follows the pixel); its
# distance to the reference bounds the references' own error.
POV_CHECK = {
    "noise_shadow": ("area 65×65, AA 0 AM1 R4 at 2× the size, averaged 2 × 2",
                     ["Declare=LightN=65", "+A0.0", "+AM1", "+R4", "+J"]),
    "noise_dof": ("blur_samples 512 at 2× the size, averaged 2 × 2",
                  ["Declare=BlurSamples=512", "-A"]),
}
TARGETS = [0.02, 0.01, 0.005]


def read_exr(path):
    """Every channel of every pixel, row by row, as floats."""
    text = subprocess.run(["oiiotool", "--dumpdata:empty=0", path], check=True,
                          capture_output=True, text=True).stdout
    values = []
    for line in text.splitlines():
        if "Pixel (" in line:
            values += [float(v) for v in line.split(":", 1)[1].split()]
    if not values:
        sys.exit("error: no pixels read from %s" % path)
    return values


def halve(values, width, height):
    """An RGB image of 2·width × 2·height averaged over 2 × 2 blocks (a box filter)."""
    out = []
    row = 2 * width * 3
    for y in range(height):
        top, bottom = 2 * y * row, (2 * y + 1) * row
        for x in range(width):
            for c in range(3):
                i = 6 * x + c
                out.append(0.25 * (values[top + i] + values[top + i + 3] +
                                   values[bottom + i] + values[bottom + i + 3]))
    return out


def rmse(image, reference):
    if len(image) != len(reference):
        sys.exit("error: images of different sizes")
    return math.sqrt(sum((a - b) ** 2 for a, b in zip(image, reference)) / len(image))


def log_slope(xs, ys):
    """Least-squares slope of log y against log x (None if some y is 0 or x has one value)."""
    if min(ys) <= 0 or len(set(xs)) < 2:
        return None
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    mx, my = statistics.mean(lx), statistics.mean(ly)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)


def pareto(points):
    """The points no other point beats in both trace time and RMSE, fastest first."""
    front = []
    for p in sorted(points, key=lambda p: (p["trace"], p["rmse"])):
        if not front or p["rmse"] < front[-1]["rmse"]:
            front.append(p)
    return front


def time_at(front, target):
    """(trace time at RMSE = target interpolated along the front linearly in log-log, bound)
    with bound "" for an interpolated time, "≤" when even the fastest setting is below the
    target (the time is an upper bound), or (None, "") when no setting reaches it."""
    if not front:
        return None, ""
    if front[0]["rmse"] <= target:
        return front[0]["trace"], "" if front[0]["rmse"] == target else "≤"
    for a, b in zip(front, front[1:]):
        if a["rmse"] >= target >= b["rmse"]:
            w = math.log(a["rmse"] / target) / math.log(a["rmse"] / b["rmse"])
            return math.exp((1 - w) * math.log(a["trace"]) + w * math.log(b["trace"])), ""
    return None, ""


def compare(kerf, pov):
    """(ratio kerf/POV-Ray, its bound, whether the 0.5 target is met: True, False or None when
    the bounds leave it open)."""
    (k, kb), (p, pb) = kerf, pov
    if k is None or p is None or p <= 0:
        return None, "", None
    ratio = k / p
    if kb and pb:
        return ratio, "?", None
    if kb:  # kerf could be faster still: the ratio is an upper bound
        return ratio, "≤", True if ratio <= 0.5 else None
    if pb:  # POV-Ray could be faster still: the ratio is a lower bound
        return ratio, "≥", False if ratio > 0.5 else None
    return ratio, "", ratio <= 0.5


class Bench:
    def __init__(self, args):
        self.args = args
        self.env = dict(os.environ, POVINI=os.path.join(args.out, "empty.ini"))
        with open(self.env["POVINI"], "w", encoding="utf-8"):
            pass
        self.scenes = os.path.join(args.root, "bench", "scenes")
        self.size = ["--width", str(args.width), "--height", str(args.height)]

    def kerf(self, scene, spp, sampler, tag, extra=()):
        """One kerf render: (image path, {trace, wall}, command)."""
        image = os.path.join(self.args.out, "%s.%s.exr" % (scene, tag))
        command = [self.args.kerf, "render", os.path.join(self.scenes, scene + ".kerf"),
                   "-o", image, *self.size, "--spp", str(spp), "--sampler", sampler,
                   "--threads", str(self.args.threads), "--stats", "--quiet", *extra]
        wall, text = run_timed(command, image.replace(".exr", ".log"))
        return image, {"trace": kerf_stats(text)["trace"], "wall": wall}, command

    def pov(self, scene, extra, tag, scale=1):
        image = os.path.join(self.args.out, "%s.%s.exr" % (scene, tag))
        command = ["povray", "+I" + os.path.join(self.scenes, scene + ".pov"), "+O" + image,
                   "+FE", "+W%d" % (scale * self.args.width),
                   "+H%d" % (scale * self.args.height), "+Q9",
                   "+WT%d" % self.args.threads, "-D", "-V", *extra]
        wall, text = run_timed(command, image.replace(".exr", ".log"), self.env)
        return image, {"trace": pov_stats(text)["trace"], "wall": wall}, command

    def samplers(self, scene):
        """Part 1: RMSE and trace time per sampler and spp (one run each)."""
        args = self.args
        load_before = load_average()
        ref_image, ref_time, ref_cmd = self.kerf(scene, args.ref_spp, "jittered", "ref")
        reference = read_exr(ref_image)
        result = {"scene": scene, "reference_command": shown(ref_cmd, args.root),
                  "reference_trace": ref_time["trace"],
                  "reference_mean": statistics.mean(reference), "rows": {}}
        if not args.no_check_reference:
            check_image, _, _ = self.kerf(scene, args.check_spp, "lattice", "ref_lattice")
            result["reference_gap"] = rmse(read_exr(check_image), reference)
            result["check_spp"] = args.check_spp
        for sampler in args.samplers:
            row = []
            for spp in args.spps:
                image, timing, _ = self.kerf(scene, spp, sampler, "%s%d" % (sampler, spp))
                row.append({"spp": spp, "rmse": rmse(read_exr(image), reference), **timing})
            result["rows"][sampler] = {
                "points": row,
                "slope": log_slope([p["spp"] for p in row], [p["rmse"] for p in row])}
        result["load"] = [load_before, load_average()]
        return result, reference

    def timed(self, render, runs):
        """Median trace and wall time of `runs` renders (the first one's image is kept)."""
        image, first, command = render(0)
        times = [first] + [render(i)[1] for i in range(1, runs)]
        return image, {"trace": statistics.median(t["trace"] for t in times),
                       "wall": statistics.median(t["wall"] for t in times),
                       "traces": [t["trace"] for t in times]}, command

    def against_pov(self, scene, kerf_reference):
        """Part 2: each renderer against its own reference; time at equal RMSE."""
        args = self.args
        load_before = load_average()
        result = {"scene": scene, "kerf": {}, "targets": {}}
        for sampler in KERF_POV_SAMPLERS:
            points = []
            for spp in args.pov_spps:
                image, timing, command = self.timed(
                    lambda i: self.kerf(scene, spp, sampler, "pk_%s%d" % (sampler, spp)),
                    args.runs)
                points.append({"label": "%s %d spp" % (sampler, spp),
                               "rmse": rmse(read_exr(image), kerf_reference), **timing,
                               "command": shown(command, args.root)})
            result["kerf"][sampler] = points
        points = []
        for noise in args.kerf_noise:
            image, timing, command = self.timed(
                lambda i: self.kerf(scene, 256, "jittered", "pk_noise%g" % noise,
                                    ["--noise", repr(noise)]), args.runs)
            points.append({"label": "jittered, 256 spp, noise %g" % noise,
                           "rmse": rmse(read_exr(image), kerf_reference), **timing,
                           "command": shown(command, args.root)})
        result["kerf"]["adaptive"] = points
        label, extra = POV_REFERENCE[scene]
        if args.quick:
            label, extra = QUICK_POV_REFERENCE[scene]
        ref_image, ref_time, ref_cmd = self.pov(scene, extra, "pov_ref")
        pov_reference = read_exr(ref_image)
        result["pov_reference"] = {"label": label, "command": shown(ref_cmd, args.root),
                                   "trace": ref_time["trace"],
                                   "mean": statistics.mean(pov_reference)}
        if not args.no_check_reference:
            label, extra = POV_CHECK[scene]
            if args.quick:
                label, extra = QUICK_POV_REFERENCE[scene]
                label += " at 2× the size, averaged 2 × 2"
            check_image, _, _ = self.pov(scene, extra, "pov_ref_check", scale=2)
            check = halve(read_exr(check_image), args.width, args.height)
            result["pov_reference"]["gap"] = rmse(check, pov_reference)
            result["pov_reference"]["check"] = label
        points = []
        for index, (label, extra) in enumerate(POV_SETTINGS[scene]):
            image, timing, command = self.pov(scene, extra, "pov%d" % index)
            points.append({"label": label, "rmse": rmse(read_exr(image), pov_reference),
                           **timing, "traces": [timing["trace"]],
                           "command": shown(command, args.root), "extra": extra,
                           "index": index})
        # Only the front decides the comparison: time its settings `runs` times in all.
        for p in pareto([p for p in points if p["rmse"] > 0]):
            more = [self.pov(scene, p["extra"], "pov%d" % p["index"])[1]
                    for _ in range(args.runs - 1)]
            p["traces"] += [t["trace"] for t in more]
            p["trace"] = statistics.median(p["traces"])
            p["wall"] = statistics.median([p["wall"]] + [t["wall"] for t in more])
            p["front"] = True
        result["pov"] = points
        pov_front = pareto([p for p in points if p.get("front")])
        for target in args.targets:
            entry = {"pov": time_at(pov_front, target)}
            for curve in KERF_CURVES:
                entry[curve] = time_at(pareto(result["kerf"][curve]), target)
            # The fastest kerf curve there (an upper bound only if every reaching curve's is).
            reached = [entry[c] for c in KERF_CURVES if entry[c][0] is not None]
            entry["best"] = min(reached, key=lambda t: (t[0], t[1])) if reached else (None, "")
            result["targets"][repr(target)] = entry
        result["load"] = [load_before, load_average()]
        return result


# ---------------------------------------------------------------------------------------------
# The report: markdown for docs/BENCHMARKS.md.

BEGIN = "<!-- BEGIN GENERATED by bench/run_noise_bench.sh: do not edit by hand -->"
END = "<!-- END GENERATED by bench/run_noise_bench.sh -->"


def fmt(x, digits=4):
    return "—" if x is None else "%.*g" % (digits, x)


def seconds(timed):
    """A (time, bound) pair from time_at as a table cell."""
    return "—" if timed[0] is None else "%s%s s" % (timed[1], fmt(timed[0], 3))


def met(ok):
    return "met" if ok else "**NOT met**"


def sampler_table(result, spps):
    out = ["#### %s" % result["scene"], "",
           "Reference: `%s` (trace %.1f s, mean %.4f)." % (
               result["reference_command"], result["reference_trace"],
               result["reference_mean"])]
    if "reference_gap" in result:
        out[-1] += (" RMSE between it and a %d-spp `--sampler lattice` render: %.2g (about "
                    "the root sum of squares of both references' errors: a bound on the "
                    "reference's own)." % (result["check_spp"], result["reference_gap"]))
    out += ["", "| sampler | %s | slope |" % " | ".join("%d spp" % s for s in spps),
            "|---|%s---:|" % ("---:|" * len(spps))]
    for sampler, row in result["rows"].items():
        out.append("| %s | %s | %s |" % (sampler, " | ".join(
            "%s (%.3f s)" % (fmt(p["rmse"], 3), p["trace"]) for p in row["points"]),
            fmt(row["slope"], 3)))
    rows = result["rows"]
    if "random" in rows:
        for sampler in ("jittered", "lattice"):
            if sampler in rows:
                ok = all(p["rmse"] < r["rmse"] for p, r in
                         zip(rows[sampler]["points"], rows["random"]["points"]))
                out.append("")
                out.append("- %s beats random at every count: %s" % (sampler, met(ok)))
    out.append("")
    out.append("Load %.1f → %.1f." % tuple(result["load"]))
    return "\n".join(out)


def pov_tables(result):
    ref = result["pov_reference"]
    out = ["#### %s against POV-Ray" % result["scene"], "",
           "POV-Ray's reference: %s, `%s` (trace %.1f s, mean %.4f)." % (
               ref["label"], ref["command"], ref["trace"], ref["mean"])]
    if "gap" in ref:
        out[-1] += " RMSE between it and %s: %.2g." % (ref["check"], ref["gap"])
    out += ["",
           "| renderer | setting | RMSE | trace (s) | wall (s) |", "|---|---|---:|---:|---:|"]
    for sampler, points in result["kerf"].items():
        for p in points:
            out.append("| kerf | %s | %s | %.3f | %.3f |" % (p["label"], fmt(p["rmse"], 3),
                                                           p["trace"], p["wall"]))
    for p in result["pov"]:
        mark = "" if p.get("front") else " (1 run; off the front)"
        out.append("| POV-Ray | %s%s | %s | %.3f | %.3f |" % (
            p["label"], mark, fmt(p["rmse"], 3), p["trace"], p["wall"]))
    out += ["", "Trace time at equal RMSE (interpolated along each front; \"best\" is the "
            "fastest of kerf's curves at that RMSE; ≤ where a renderer's fastest setting is "
            "already below the RMSE, so its time there is an upper bound):", "",
            "| RMSE | POV-Ray | %s |" % " | ".join("kerf %s | ratio" % c
                                               for c in KERF_CURVES + ["best"]),
            "|---:|---:|%s" % ("---:|---:|" * (len(KERF_CURVES) + 1))]
    lines = []
    for target, entry in result["targets"].items():
        pov = entry["pov"]
        cells = ["%s" % target, seconds(pov)]
        for sampler in KERF_CURVES + ["best"]:
            k = entry.get(sampler)
            ratio, bound, ok = compare(k, pov)
            cells += [seconds(k), bound + fmt(ratio, 2)]
            if sampler not in ("jittered", "best"):
                continue  # the table has the other curves; the checks judge these two
            if ratio is not None:
                verdict = "open (bounds only)" if ok is None else met(ok)
                lines.append("- %s, RMSE %s, kerf %s ≤ 0.5× POV-Ray's trace time: %s%.2f× — "
                             "%s" % (result["scene"], target, sampler, bound, ratio, verdict))
            else:
                lines.append("- %s, RMSE %s, kerf %s: not compared (a front does not reach "
                             "this RMSE)" % (result["scene"], target, sampler))
        out.append("| %s |" % " | ".join(cells))
    out += [""] + lines + ["", "Load %.1f → %.1f." % tuple(result["load"])]
    return "\n".join(out)


def section(report, args):
    v = report["versions"]
    out = [BEGIN, "## Noise against time (issue 10 §4)", "",
           "Run %s to %s; %s; %s; %s. Images %d × %d, %d threads for both renderers; "
           "`uptime` before: `%s`; after: `%s`." % (
               report["start"], report["end"], v.get("kerf", "?"), v.get("povray", "?"),
               v.get("cpu", "?"), args.width, args.height, args.threads,
               report["uptime_before"], report["uptime_after"]), "",
           "Error: the RMSE of the linear float EXR (every pixel, R, G and B alike; POV-Ray "
           "writes half floats) against the renderer's own reference. kerf's reference is "
           "%d spp `--sampler jittered`. Sampler tables: one run each, kerf's `--stats` "
           "trace time in brackets; slope: least squares of log RMSE on log spp. POV-Ray "
           "comparison: trace times (POV-Ray's \"Trace Time\", kerf's `--stats` trace), "
           "median of %d on each front." % (args.ref_spp, args.runs), "",
           "### Samplers", ""]
    for result in report["samplers"]:
        out += [sampler_table(result, args.spps), ""]
    if report["pov"]:
        out += ["### Against POV-Ray 3.7", ""]
        for result in report["pov"]:
            out += [pov_tables(result), ""]
    out.append(END)
    return "\n".join(out) + "\n"


def write_doc(path, text):
    """Replaces the generated noise section (or appends it at the end)."""
    with open(path, encoding="utf-8") as f:
        doc = f.read()
    start, end = doc.find(BEGIN), doc.find(END)
    if start >= 0 and end > start:
        doc = doc[:start] + text + doc[end + len(END) + 1:]
    else:
        doc = doc.rstrip("\n") + "\n\n" + text
    with open(path, "w", encoding="utf-8") as f:
        f.write(doc)


def uptime():
    return subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser.add_argument("--kerf", required=True, help="the kerf executable")
    parser.add_argument("--root", default=root, help=argparse.SUPPRESS)
    parser.add_argument("--out", default=os.path.join(root, "bench", "out", "noise"))
    parser.add_argument("--scenes", nargs="+", default=SCENES, choices=SCENES)
    parser.add_argument("--samplers", nargs="+", default=SAMPLERS, choices=SAMPLERS)
    parser.add_argument("--spps", nargs="+", type=int, default=SPPS)
    parser.add_argument("--pov-spps", nargs="+", type=int, default=KERF_POV_SPPS)
    parser.add_argument("--check-spp", type=int, default=1024,
                        help="spp of the lattice render the reference is checked against")
    parser.add_argument("--kerf-noise", nargs="+", type=float, default=KERF_NOISE)
    parser.add_argument("--ref-spp", type=int, default=4096)
    parser.add_argument("--targets", nargs="+", type=float, default=TARGETS,
                        help="RMSE levels at which the renderers' times are compared")
    parser.add_argument("--width", type=int, default=200)
    parser.add_argument("--height", type=int, default=150)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--runs", type=int, default=3, help="timed runs for part 2 (median)")
    parser.add_argument("--no-pov", action="store_true", help="part 1 only")
    parser.add_argument("--no-check-reference", action="store_true",
                        help="skip the lattice check of the references")
    parser.add_argument("--quick", action="store_true",
                        help="64 x 48, 256-spp references, one run: a look; doc untouched")
    args = parser.parse_args()
    args.kerf = os.path.abspath(args.kerf)
    if args.quick:
        args.width, args.height, args.ref_spp, args.runs = 64, 48, 256, 1
        args.check_spp = 256
        args.pov_spps = [s for s in args.pov_spps if s <= 32]
        args.spps = [s for s in args.spps if s < args.ref_spp]
    os.makedirs(args.out, exist_ok=True)

    report = {"versions": versions(args.kerf), "uptime_before": uptime(),
              "start": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
              "size": [args.width, args.height], "ref_spp": args.ref_spp, "runs": args.runs,
              "threads": args.threads, "targets": args.targets, "quick": args.quick,
              "samplers": [], "pov": []}
    # One untimed render each, so neither renderer pays for a cold page cache.
    bench = Bench(args)
    bench.kerf(args.scenes[0], 1, "jittered", "warm")
    if not args.no_pov:
        bench.pov("noise_shadow", ["Declare=LightN=2", "-A"], "warm")
    for scene in args.scenes:
        result, reference = bench.samplers(scene)
        report["samplers"].append(result)
        print(sampler_table(result, args.spps))
        if not args.no_pov and scene in POV_SETTINGS:
            comparison = bench.against_pov(scene, reference)
            report["pov"].append(comparison)
            print(pov_tables(comparison))
    report["uptime_after"] = uptime()
    report["end"] = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    with open(os.path.join(args.out, "results.json"), "w", encoding="utf-8") as f:
        json.dump(report, f, indent=1)
    text = section(report, args)
    print(text)
    if not args.quick:
        write_doc(os.path.join(args.root, "docs", "BENCHMARKS.md"), text)


if __name__ == "__main__":
    main()
