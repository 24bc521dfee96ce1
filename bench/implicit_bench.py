#!/usr/bin/env python3
"""The implicit-surface benchmark of issue 8; bench/run_implicit_bench.sh builds the checker
and the scenes, then calls this.

Scenes (bench/gen_implicit_scenes.py; cup is models/cup.kerf at its own settings):
  gyroid  800 x 600, 2 threads, kerf against POV-Ray's isosurface at max_gradient 11 and 1.1
  barth   512 x 512, 1 thread, kerf against POV-Ray at max_gradient 400, 150 and 1.1
  blobs   800 x 600, 2 threads, kerf only (its --accel configurations against each other)
  cup     models/cup.kerf (800 x 600, spp 4), 2 threads, kerf against the baseline build

Each kerf configuration (--kerf-config NAME="OPTIONS"; a configuration whose options kerf
rejects is skipped and said so), the baseline kerf (cup) and each POV-Ray max_gradient run
RUNS times, round robin, after one untimed warm-up; medians are reported. Then the checks,
once each, at the timed settings except spp 1 (the depth AOV is the pixel-centre hit at any spp):
  hit mask: every configuration's depth AOV against a reference kerf render (REFERENCE
    OPTIONS, by default --method interval --tolerance 1e-9, plus --accel none when kerf has
    it): pixels hit by one and not the other, largest relative depth difference over the rest,
    and (bench/thin_spans.py) which disagreements are spans thinner than the tolerance;
  POV-Ray's holes: the floorless scene (NAME.mask.*) rendered by the reference kerf and by
    POV-Ray with +UA at each max_gradient: pixels POV-Ray misses where kerf hits.
Writes bench/out/implicit/results.json and the implicit part of docs/BENCHMARKS.md.
"""
import argparse
import json
import os
import re
import shlex
import subprocess
import sys
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from run_bench import (kerf_stats, load_average, pov_stats, run_timed, shown,  # noqa: E402
                       summarize, versions)
import implicit_report  # noqa: E402
import thin_spans  # noqa: E402

# name -> settings. "file" is relative to the repository; "size" None keeps the model's own.
SCENES = {
    "gyroid": {"file": "bench/scenes/gyroid", "size": (800, 600), "spp": 1, "threads": 2,
               "pov_gradients": ["11", "1.1"]},
    "barth": {"file": "bench/scenes/barth", "size": (512, 512), "spp": 1, "threads": 1,
              "pov_gradients": ["400", "150", "1.1"]},
    "blobs": {"file": "bench/scenes/blobs", "size": (800, 600), "spp": 1, "threads": 2,
              "pov_gradients": []},
    "cup": {"file": "models/cup", "size": None, "spp": None, "threads": 2,
            "pov_gradients": [], "baseline": True},
}
POV_DEFAULT_GRADIENT = "1.1"  # POV-Ray 3.7's max_gradient when the scene gives none
REFERENCE_OPTIONS = "--method interval --tolerance 1e-9"
KERF_KEYS = ["wall", "trace", "rays per second", "rays in total", "camera rays", "shadow rays",
             "interval evaluations", "root-finder steps", "primitive tests", "parse + compile",
             "tolerance", "cells visited per ray", "octree build", "octree memory",
             "octree cells"]


def kerf_stats_all(text):
    """kerf_stats plus the labels its pattern leaves out (octree lines are absent when kerf
    builds no octree)."""
    stats = kerf_stats(text)
    match = re.search(r"cells visited / ray\s+([0-9.e+\-]+)", text)
    if match:
        stats["cells visited per ray"] = float(match.group(1))
    return stats


def kerf_command(kerf, scene, path, output, extra, spp=None):
    """kerf render of path with the scene's settings (spp overrides the scene's)."""
    command = [kerf, "render", path, "-o", output, "--threads", str(scene["threads"]),
               "--stats", "--quiet"]
    if scene["size"]:
        command += ["--width", str(scene["size"][0]), "--height", str(scene["size"][1])]
    spp = spp or scene["spp"]
    if spp:
        command += ["--spp", str(spp)]
    return command + extra


def pov_command(scene, path, output, gradient, alpha=False):
    width, height = scene["size"]
    return ["povray", "+I" + path, "+O" + output, "+W%d" % width, "+H%d" % height, "-A", "+Q9",
            "+WT%d" % scene["threads"], "-D", "-V", "+FN", "Declare=MaxGradient=" + gradient] \
        + (["+UA"] if alpha else [])


def accepts(kerf, options, args):
    """Whether kerf renders a tiny image with these options (an unknown option exits non-zero)."""
    if not options:
        return True
    probe = os.path.join(args.root, "bench", "scenes", "gyroid.kerf")
    result = subprocess.run([kerf, "render", probe, "-o", os.path.join(args.out, "probe.png"),
                             "--width", "4", "--height", "4", "--quiet", *options],
                            capture_output=True, text=True)
    return result.returncode == 0


def pov_gradient_found(text):
    """The largest gradient POV-Ray met, from its max_gradient warning (None if it gave none)."""
    match = re.search(r"maximum gradient found was ([0-9.]+)", text.replace("\n", " "))
    return float(match.group(1)) if match else None


def hit_mask(args, mode, first, second, diff, tolerance=None):
    command = [args.hit_mask, mode, first, second, "--diff", diff,
               "--list", diff.replace(".png", ".txt")]
    if tolerance is not None:
        command += ["--tolerance", repr(tolerance)]
    return json.loads(subprocess.run(command, check=True, capture_output=True, text=True).stdout)


def bench_scene(name, args, env):
    scene = SCENES[name]
    base = os.path.join(args.root, scene["file"])
    out = lambda suffix: os.path.join(args.out, name + suffix)  # noqa: E731
    variants = [("kerf " + label, args.kerf, options) for label, options in args.configs]
    if scene.get("baseline") and args.kerf_baseline:
        variants.append(("baseline", args.kerf_baseline, []))
    commands = {label: kerf_command(kerf, scene, base + ".kerf", out(".%s.png" % slug(label)),
                                    options)
                for label, kerf, options in variants}
    for gradient in scene["pov_gradients"]:
        commands[pov_label(gradient)] = pov_command(scene, base + ".pov",
                                                        out(".pov%s.png" % gradient), gradient)
    runs = {label: [] for label in commands}
    load_before = load_average()
    for _ in range(args.runs):
        for label, command in commands.items():
            pov = label.startswith("POV-Ray")
            wall, text = run_timed(command, out(".%s.log" % slug(label)), env if pov else None)
            stats = pov_stats(text) if pov else kerf_stats_all(text)
            if pov:
                stats["gradient found"] = pov_gradient_found(text)
            runs[label].append(dict(stats, wall=wall))
    load_after = load_average()

    rows = []
    for label, command in commands.items():
        pov = label.startswith("POV-Ray")
        keys = ["wall", "trace", "rays", "shadow rays"] if pov else KERF_KEYS
        row = {"label": label, "command": shown(command, args.root),
               "median": summarize(runs[label], keys),
               "trace_range": [min(r["trace"] for r in runs[label]),
                               max(r["trace"] for r in runs[label])]}
        if pov:
            m = row["median"]
            m["rays per second"] = (m["rays"] + m["shadow rays"]) / m["trace"]
            row["gradient_found"] = runs[label][-1]["gradient found"]
        rows.append(row)
    result = {"scene": name, "threads": scene["threads"], "size": scene["size"],
              "load_before": load_before, "load_after": load_after, "rows": rows}
    if not args.no_checks:
        checks(name, scene, base, variants, result, args, env)
    for row in rows:
        print("%-8s %-22s trace %8.3f s  wall %8.3f s" % (
            name, row["label"], row["median"]["trace"], row["median"]["wall"]), flush=True)
    return result


def checks(name, scene, base, variants, result, args, env):
    """Hit masks against the reference kerf render, and POV-Ray's coverage against kerf's."""
    out = lambda suffix: os.path.join(args.out, name + suffix)  # noqa: E731
    reference = out(".reference.exr")
    command = kerf_command(args.kerf, scene, base + ".kerf", out(".reference.png"),
                           args.reference_options + ["--aov", "depth=" + reference], spp=1)
    _, text = run_timed(command, out(".reference.log"))
    result["reference"] = {"command": shown(command, args.root),
                           "trace": kerf_stats(text).get("trace")}
    rows = {row["label"]: row for row in result["rows"]}
    for label, kerf, options in variants:
        depth = out(".%s.exr" % slug(label))
        command = kerf_command(kerf, scene, base + ".kerf", out(".%s.depth.png" % slug(label)),
                               options + ["--aov", "depth=" + depth], spp=1)
        _, text = run_timed(command, out(".%s.depth.log" % slug(label)))
        tolerance = kerf_stats(text).get("tolerance", 0.0)
        mask = hit_mask(args, "depth", depth, reference, out(".%s.maskdiff.png" % slug(label)),
                        tolerance)
        if name in thin_spans.FIELDS:
            width, height = scene["size"] or (800, 600)  # cup's own size
            mask["spans"] = thin_spans.classify(name, out(".%s.maskdiff.txt" % slug(label)),
                                                width, height, tolerance)
        rows[label]["mask"] = mask
    add_against_none(result, args.out, args.hit_mask)
    if not scene["pov_gradients"]:
        return
    # Coverage: the floorless scene, by the reference kerf and by POV-Ray with alpha.
    coverage_ref = reference  # a scene without a floor is its own mask
    if os.path.exists(base + ".mask.kerf"):
        coverage_ref = out(".mask.reference.exr")
        command = kerf_command(args.kerf, scene, base + ".mask.kerf", out(".mask.reference.png"),
                               args.reference_options + ["--aov", "depth=" + coverage_ref], spp=1)
        run_timed(command, out(".mask.reference.log"))
    for gradient in scene["pov_gradients"]:
        image = out(".mask.pov%s.png" % gradient)
        command = pov_command(scene, base + ".mask.pov", image, gradient, alpha=True)
        _, text = run_timed(command, out(".mask.pov%s.log" % gradient), env)
        coverage = hit_mask(args, "coverage", coverage_ref, image,
                            out(".mask.pov%s.diff.png" % gradient))
        coverage["gradient_found"] = pov_gradient_found(text)
        coverage["command"] = shown(command, args.root)
        rows[pov_label(gradient)]["coverage"] = coverage


def add_against_none(result, out, tool):
    """Each kerf configuration's depth against `--accel none`'s (the same surfaces within the
    tolerance, as issue 8 requires of the octree); True if anything was added."""
    name, added = result["scene"], False
    none = os.path.join(out, "%s.kerf-none.exr" % name)
    if not os.path.exists(none):
        return False
    for row in result["rows"]:
        mask = row.get("mask")
        if not mask or row["label"] == "kerf none" or "spans" in mask.get("against_none", {}):
            continue
        depth = os.path.join(out, "%s.%s.exr" % (name, slug(row["label"])))
        command = [tool, "depth", depth, none, "--tolerance", repr(mask["tolerance"]),
                   "--list", os.path.join(out, "%s.%s.vsnone.txt" % (name, slug(row["label"])))]
        against = json.loads(subprocess.run(command, check=True, capture_output=True,
                                            text=True).stdout)
        if name in thin_spans.FIELDS:
            # The surface one sees and the other does not is the nearer one: its span's
            # thickness tells whether dropping it is within the tolerance's rule.
            nearer = command[-1].replace(".txt", ".nearer.txt")
            with open(command[-1], encoding="utf-8") as src, \
                    open(nearer, "w", encoding="utf-8") as dst:
                for line in src:
                    i, j, a, b = line.split()
                    dst.write("%s %s %s %r\n" % (i, j, a, min(float(a), float(b))))
            width, height = result["size"] or (800, 600)  # cup's own size
            against["spans"] = thin_spans.classify(name, nearer, width, height,
                                                   mask["tolerance"])
        mask["against_none"] = against
        added = True
    return added


def add_thin_spans(report, out):
    """Classifies the disagreements of a results.json written before bench/thin_spans.py
    existed, from the pixel lists beside it; True if anything was added."""
    added = False
    for result in report["results"]:
        name = result["scene"]
        for row in result["rows"]:
            mask = row.get("mask")
            if name not in thin_spans.FIELDS or not mask or "spans" in mask:
                continue
            listing = os.path.join(out, "%s.%s.maskdiff.txt" % (name, slug(row["label"])))
            width, height = result["size"] or (800, 600)  # cup's own size
            mask["spans"] = thin_spans.classify(name, listing, width, height, mask["tolerance"])
            added = True
    return added


def pov_label(gradient):
    return "POV-Ray %s%s" % (gradient, " (default)" if gradient == POV_DEFAULT_GRADIENT else "")


def slug(label):
    return label.split(" (")[0].replace(" ", "-").replace("/", "-")


def parse_configs(texts):
    configs = []
    for text in texts or ["default="]:
        label, _, options = text.partition("=")
        configs.append((label, shlex.split(options)))
    return configs


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--kerf", help="the kerf under test (required unless --from-json)")
    parser.add_argument("--kerf-baseline", help="the kerf to compare with on cup")
    parser.add_argument("--hit-mask", help="the hit_mask executable (required unless --from-json)")
    parser.add_argument("--kerf-config", nargs="+", metavar="NAME=OPTIONS",
                        help='kerf configurations, e.g. none="--accel none" '
                        'octree="--accel octree" (default: one, "default", no options)')
    parser.add_argument("--reference-options", default=None,
                        help='options of the reference kerf render (default: "%s", plus '
                        '"--accel none" when kerf accepts it)' % REFERENCE_OPTIONS)
    parser.add_argument("--kerf-note", default="",
                        help="what the kerf under test is, for the report (e.g. its commit)")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--scenes", nargs="+", default=list(SCENES), choices=list(SCENES))
    parser.add_argument("--no-checks", action="store_true", help="skip hit masks and coverage")
    parser.add_argument("--out", default=os.path.join(here, "out", "implicit"))
    parser.add_argument("--doc", help="the document whose implicit part is rewritten; '-' for "
                        "none (default: docs/BENCHMARKS.md after a full run, none otherwise)")
    parser.add_argument("--from-json", metavar="RESULTS",
                        help="only rewrite the report from an earlier run's results.json "
                        "(with --doc FILE)")
    args = parser.parse_args()
    args.root = root
    if args.from_json:
        with open(args.from_json, encoding="utf-8") as f:
            report = json.load(f)
        out = os.path.dirname(os.path.abspath(args.from_json))
        tool = args.hit_mask or os.path.join(root, "build", "bench-reference", "hit_mask")
        added = [add_against_none(result, out, tool) for result in report["results"]]
        if add_thin_spans(report, out) or any(added):
            with open(args.from_json, "w", encoding="utf-8") as f:
                json.dump(report, f, indent=1)
        markdown = implicit_report.markdown(report)
        print(markdown)
        if args.doc and args.doc != "-":
            implicit_report.update(args.doc, markdown)
            print("wrote", args.doc)
        return
    if not args.kerf or not args.hit_mask:
        parser.error("--kerf and --hit-mask are required")
    os.makedirs(args.out, exist_ok=True)
    empty_ini = os.path.join(args.out, "empty.ini")
    open(empty_ini, "w").close()
    env = dict(os.environ, POVINI=empty_ini)  # only the command line sets POV-Ray's options

    skipped = []
    args.configs = []
    for label, options in parse_configs(args.kerf_config):
        (args.configs if accepts(args.kerf, options, args) else skipped).append((label, options))
    for label, options in skipped:
        print("kerf rejects %s (%s): configuration skipped" % (label, " ".join(options)))
    if args.reference_options is None:
        args.reference_options = REFERENCE_OPTIONS + (
            " --accel none" if accepts(args.kerf, ["--accel", "none"], args) else "")
    args.reference_options = shlex.split(args.reference_options)

    started = time.time()
    gyroid = os.path.join(root, "bench", "scenes", "gyroid")
    run_timed([args.kerf, "render", gyroid + ".kerf", "-o", os.path.join(args.out, "warm.png"),
               "--width", "80", "--height", "60", "--quiet"], os.path.join(args.out, "warm.log"))
    run_timed(["povray", "+I" + gyroid + ".pov", "+O" + os.path.join(args.out, "warm.png"),
               "+W80", "+H60", "-D", "-V"], os.path.join(args.out, "warm.log"), env)
    results = [bench_scene(name, args, env) for name in args.scenes]
    machine = versions(args.kerf)
    if args.kerf_baseline:
        machine["baseline"] = versions(args.kerf_baseline)["kerf"]
    report = {
        "machine": machine, "runs": args.runs, "results": results,
        "configs": [[label, " ".join(o)] for label, o in args.configs],
        "skipped": [[label, " ".join(o)] for label, o in skipped],
        "reference_options": " ".join(args.reference_options),
        "kerf": shown([args.kerf], root),
        "kerf_note": args.kerf_note,
        "kerf_baseline": shown([args.kerf_baseline], root) if args.kerf_baseline else None,
        "seconds": time.time() - started,
    }
    with open(os.path.join(args.out, "results.json"), "w", encoding="utf-8") as f:
        json.dump(report, f, indent=1)
    markdown = implicit_report.markdown(report)
    print(markdown)
    full = args.scenes == list(SCENES) and args.runs >= 5 and not args.no_checks
    if args.doc is None:
        args.doc = os.path.join(root, "docs", "BENCHMARKS.md") if full else "-"
        if not full:
            print("not a full run: docs/BENCHMARKS.md left as it is (--doc FILE writes anyway)")
    if args.doc != "-":
        implicit_report.update(args.doc, markdown)
        print("wrote", args.doc)


if __name__ == "__main__":
    main()
