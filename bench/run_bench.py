#!/usr/bin/env python3
"""Runs the kerf / POV-Ray benchmark; bench/run_bench.sh builds everything, then calls this.

For each scene of bench/scenes (written by bench/gen_scenes.py): renders it with kerf and with
POV-Ray alternately, RUNS times each, at 800 x 600, 1 sample per pixel, 2 threads; takes the
median wall time (process start to exit, the image written) and the median trace-stage time
each renderer reports (kerf --stats "trace", POV-Ray "Trace Time"); then renders kerf's depth
AOV once more and compares it pixel by pixel with bench/depth_reference (long double, closed
forms). Writes bench/out/results.json and the generated part of docs/BENCHMARKS.md.
"""
import argparse
import json
import math
import os
import re
import statistics
import subprocess
import sys
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import bench_report  # noqa: E402 (after the line above on purpose)

SCENES = ["cup", "box_minus_spheres_10", "box_minus_spheres_100", "box_minus_spheres_1000",
          "box_minus_spheres_5000", "tori", "torus1"]


def run_timed(command, log_path, env=None):
    """Runs a command with stdout and stderr into log_path; returns (wall seconds, log text)."""
    with open(log_path, "w", encoding="utf-8") as log:
        start = time.perf_counter()
        result = subprocess.run(command, stdout=log, stderr=subprocess.STDOUT, env=env)
        wall = time.perf_counter() - start
    with open(log_path, encoding="utf-8", errors="replace") as log:
        text = log.read()
    if result.returncode != 0:
        sys.exit("error: %s exited with %d; see %s\n%s" % (
            command[0], result.returncode, log_path, text[-2000:]))
    return wall, text


def kerf_stats(text):
    """The numbers of `kerf render --stats` ("  label   value" lines)."""
    stats = {}
    for line in text.splitlines():
        match = re.match(r"\s+([a-z][a-z +\-]*?)\s{2,}([0-9.e+\-]+)", line)
        if match:
            stats[match.group(1).strip()] = float(match.group(2))
    return stats


def pov_stats(text):
    """Rays, shadow rays and trace time from POV-Ray's statistics stream."""
    def number(pattern):
        match = re.search(pattern, text)
        return float(match.group(1)) if match else float("nan")
    return {
        "rays": number(r"Rays:\s+(\d+)"),
        "shadow rays": number(r"Shadow Ray Tests:\s+(\d+)"),
        "trace": number(r"Trace Time:.*\(([0-9.]+) seconds\)"),
        "parse": number(r"Parse Time:.*\(([0-9.]+) seconds\)"),
    }


def load_average():
    with open("/proc/loadavg", encoding="utf-8") as f:
        return float(f.read().split()[0])


def warm_up(args, env):
    """One untimed render by each renderer, so neither pays for a cold page cache."""
    scene = os.path.join(args.scenes_dir, "cup")
    run_timed([args.kerf, "render", scene + ".kerf", "-o", os.path.join(args.out, "warm.png"),
               "--width", "80", "--height", "60", "--quiet"], os.path.join(args.out, "warm.log"))
    run_timed(["povray", "+I" + scene + ".pov", "+O" + os.path.join(args.out, "warm.png"),
               "+W80", "+H60", "-D", "-V"], os.path.join(args.out, "warm.log"), env)


def bench_scene(name, args, env):
    scenes, out = args.scenes_dir, args.out
    image = ["--width", str(args.width), "--height", str(args.height)]
    kerf_cmd = [args.kerf, "render", os.path.join(scenes, name + ".kerf"),
                "-o", os.path.join(out, name + ".kerf.png"), *image,
                "--spp", "1", "--threads", str(args.threads), "--stats", "--quiet"]
    pov_cmd = ["povray", "+I" + os.path.join(scenes, name + ".pov"),
               "+O" + os.path.join(out, name + ".pov.png"), "+W%d" % args.width,
               "+H%d" % args.height, "-A", "+Q9", "+WT%d" % args.threads, "-D", "-V", "+FN"]
    kerf_runs, pov_runs = [], []
    load_before = load_average()
    for _ in range(args.runs):
        wall, text = run_timed(kerf_cmd, os.path.join(out, name + ".kerf.log"))
        kerf_runs.append(dict(kerf_stats(text), wall=wall))
        wall, text = run_timed(pov_cmd, os.path.join(out, name + ".pov.log"), env)
        pov_runs.append(dict(pov_stats(text), wall=wall))
    result = {
        "scene": name,
        "load_before": load_before,
        "load_after": load_average(),
        "kerf_command": shown(kerf_cmd, args.root),
        "pov_command": shown(pov_cmd, args.root),
        "kerf": summarize(kerf_runs, ["wall", "trace", "rays per second", "rays in total",
                                      "camera rays", "primitive tests", "bounds tests",
                                      "root-finder steps", "parse + compile", "setup", "write"]),
        "pov": summarize(pov_runs, ["wall", "trace", "rays", "shadow rays", "parse"]),
    }
    pov = result["pov"]
    pov["rays per second"] = (pov["rays"] + pov["shadow rays"]) / pov["trace"] \
        if pov["trace"] > 0 else float("nan")
    if not args.no_depth:
        result["depth"] = depth_error(name, args)
    print("%-24s kerf %7.3f s  POV-Ray %7.3f s  ratio %.3f  (load %.1f)" % (
        name, result["kerf"]["wall"], pov["wall"], result["kerf"]["wall"] / pov["wall"],
        result["load_after"]), flush=True)
    return result


def shown(command, root):
    """The command as the document shows it: paths relative to the repository."""
    return " ".join(part.replace(root + os.sep, "") for part in command)


def summarize(runs, keys):
    """Median of each key over the runs, plus every run's wall time."""
    summary = {k: statistics.median(r.get(k, float("nan")) for r in runs) for k in keys}
    summary["walls"] = [round(r["wall"], 4) for r in runs]
    return summary


def depth_error(name, args):
    """kerf's depth AOV against the long-double reference, at the benchmark's size."""
    exr = os.path.join(args.out, name + ".depth.exr")
    command = [args.kerf, "render", os.path.join(args.scenes_dir, name + ".kerf"),
               "-o", os.path.join(args.out, name + ".depthrun.png"), "--width", str(args.width),
               "--height", str(args.height), "--spp", "1", "--threads", str(args.threads),
               "--stats", "--quiet", "--aov", "depth=" + exr]
    _, text = run_timed(command, os.path.join(args.out, name + ".depthrun.log"))
    tolerance = kerf_stats(text).get("tolerance", 1e-6)
    reference = [args.reference, os.path.join(args.scenes_dir, name + ".ref"),
                 "--width", str(args.width), "--height", str(args.height),
                 "--compare", exr, "--tolerance", repr(tolerance),
                 "--list", os.path.join(args.out, name + ".disagree.txt")]
    output = subprocess.run(reference, check=True, capture_output=True, text=True).stdout
    return json.loads(output)


def fitted_exponent(counts, times):
    """Least-squares slope of log(time) against log(N)."""
    xs = [math.log(n) for n in counts]
    ys = [math.log(t) for t in times]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def scaling(results):
    rows = [r for r in results if r["scene"].startswith("box_minus_spheres_")]
    if len(rows) < 2:
        return None
    counts = [int(r["scene"].rsplit("_", 1)[1]) for r in rows]
    fit = {}
    for who in ("kerf", "pov"):
        for stage in ("wall", "trace"):
            fit["%s_%s" % (who, stage)] = fitted_exponent(counts, [r[who][stage] for r in rows])
    return {"counts": counts, "exponents": fit}


def versions(kerf):
    def first_line(command):
        result = subprocess.run(command, capture_output=True, text=True)
        lines = [l for l in (result.stdout + result.stderr).splitlines()
                 if l.strip() and "configuration file" not in l]
        return lines[0].strip() if lines else "?"
    cpu = "?"
    with open("/proc/cpuinfo", encoding="utf-8") as f:
        for line in f:
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    return {
        "kerf": first_line([kerf, "--version"]),
        "povray": first_line(["povray", "--version"]),
        "compiler": first_line(["c++", "--version"]),
        "cpu": cpu,
        "nproc": os.cpu_count(),
        "kernel": os.uname().release,
        "date": time.strftime("%Y-%m-%d %H:%M %Z"),
    }


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--kerf", required=True, help="the kerf executable")
    parser.add_argument("--reference", required=True, help="the depth_reference executable")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--width", type=int, default=800)
    parser.add_argument("--height", type=int, default=600)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--scenes", nargs="+", default=SCENES)
    parser.add_argument("--no-depth", action="store_true", help="skip the depth comparison")
    parser.add_argument("--out", default=os.path.join(here, "out"))
    parser.add_argument("--doc", help="the document whose generated part is rewritten; '-' "
                        "for none (default: docs/BENCHMARKS.md after a full run, none otherwise)")
    args = parser.parse_args()
    args.scenes_dir = os.path.join(here, "scenes")
    args.root = root
    os.makedirs(args.out, exist_ok=True)

    # POV-Ray reads this empty file instead of any povray.ini (user or system), so only the
    # command line sets its options.
    empty_ini = os.path.join(args.out, "empty.ini")
    open(empty_ini, "w").close()
    env = dict(os.environ, POVINI=empty_ini)

    started = time.time()
    warm_up(args, env)
    results = [bench_scene(name, args, env) for name in args.scenes]
    report = {
        "machine": versions(args.kerf),
        "settings": {"width": args.width, "height": args.height, "spp": 1,
                     "threads": args.threads, "runs": args.runs},
        "results": results,
        "scaling": scaling(results),
        "seconds": time.time() - started,
    }
    with open(os.path.join(args.out, "results.json"), "w", encoding="utf-8") as f:
        json.dump(report, f, indent=1)
    markdown = bench_report.markdown(report)
    print(markdown)
    full = (args.scenes == SCENES and args.runs >= 5 and args.no_depth is False
            and (args.width, args.height, args.threads) == (800, 600, 2))
    if args.doc is None:
        args.doc = os.path.join(root, "docs", "BENCHMARKS.md") if full else "-"
        if not full:
            print("not a full run: docs/BENCHMARKS.md left as it is (--doc FILE writes anyway)")
    if args.doc != "-":
        bench_report.update_document(args.doc, markdown)
        print("wrote", args.doc)


if __name__ == "__main__":
    main()
