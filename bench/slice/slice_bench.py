#!/usr/bin/env python3
"""The slicing benchmark (issue 11 §5): OpenSCAD's projection(cut = true) at $fn 16 to 128
against `kerf slice` at tolerances 1e-3 to 1e-10, on the classic cup and the cube with 1000
spherical voids, whole-process time (hyperfine, median) beside the section's area error
against the closed form. Prints a Markdown table; writes only into --out.

Run through bench/run_slice_bench.sh (see its header for the options).
"""
import argparse
import json
import math
import os
import shlex
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the sources
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from section_area import file_area  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

# name → (OpenSCAD model, kerf model, kerf's cut plane, analytic area, what the area is)
MODELS = {
    "cup": (os.path.join(HERE, "cup.scad"), os.path.join(HERE, "cup.kerf"), "z=1.2",
            math.pi * (1.2 ** 2 - 1.08 ** 2) + 0.2 * 0.2, "π(1.2² − 1.08²) + 0.2²"),
    "voids": (os.path.join(HERE, "voids.scad"), os.path.join(ROOT, "models", "voids.kerf"), "z=5.5",
              100.0 - 100 * math.pi * 0.4 ** 2, "10² − 100·π·0.4²"),
}


def hyperfine(command, runs, json_path):
    """Median and standard deviation of the wall time, and the mean CPU time (user + system),
    in seconds, of `runs` whole-process runs after one warm-up."""
    subprocess.run(["hyperfine", "-N", "-w", "1", "-r", str(runs), "--export-json", json_path,
                    "--style", "none", command], check=True, stdout=subprocess.DEVNULL)
    with open(json_path) as f:
        result = json.load(f)["results"][0]
    return result["median"], result["stddev"] or 0.0, result["user"] + result["system"]


def timed_once(argv, timeout, log_path):
    """One run under `timeout` with /usr/bin/time -v: (wall s, CPU s, max RSS MB) or None."""
    command = ["/usr/bin/time", "-v", "timeout", str(timeout)] + argv
    with open(log_path, "w") as log:
        done = subprocess.run(command, stdout=log, stderr=subprocess.STDOUT)
    text = open(log_path).read()
    if done.returncode != 0:
        return None
    wall = [l for l in text.splitlines() if "Elapsed (wall clock)" in l][0].split(": ")[-1]
    seconds = sum(float(part) * 60 ** k for k, part in enumerate(reversed(wall.split(":"))))
    field = lambda name: [l for l in text.splitlines() if name in l][0].split(": ")[-1]
    cpu = float(field("User time (seconds)")) + float(field("System time (seconds)"))
    return seconds, cpu, int(field("Maximum resident set size")) / 1024.0


def kerf_has_slice(kerf):
    """Whether `kerf --help` lists a slice subcommand (`kerf slice --help` exits 0 either way:
    the help is printed before the unknown subcommand is noticed)."""
    text = subprocess.run([kerf, "--help"], capture_output=True, text=True).stdout
    return any(line.split()[:1] == ["slice"] for line in text.splitlines())


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--kerf", required=True)
    parser.add_argument("--openscad", default="openscad")
    parser.add_argument("--out", required=True, help="folder for the outputs and logs")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--models", default="cup,voids")
    parser.add_argument("--fn", default="16,32,64,128", help="OpenSCAD $fn values for the cup")
    parser.add_argument("--voids-fn", default="16",
                        help="OpenSCAD $fn values for the voids cube, one run each ('' for none)")
    parser.add_argument("--voids-timeout", type=int, default=2700, help="seconds per OpenSCAD run")
    parser.add_argument("--tolerances", default="1e-3,1e-4,1e-5,1e-6,1e-7,1e-8,1e-9,1e-10")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    have_kerf = kerf_has_slice(args.kerf)
    if not have_kerf:
        print(f"slice_bench: {args.kerf} has no 'slice' command yet: kerf rows skipped", file=sys.stderr)

    rows = []  # (model, tool, setting, median s, sd s, CPU s, area, relative error, note)
    for name in args.models.split(","):
        scad, kerf_model, plane, exact, _ = MODELS[name]
        fns = args.fn if name == "cup" else args.voids_fn
        for fn in [int(v) for v in fns.split(",") if v]:
            svg = os.path.join(args.out, f"{name}_openscad_fn{fn}.svg")
            dxf = os.path.join(args.out, f"{name}_openscad_fn{fn}.dxf")
            argv = [args.openscad, "-o", svg, "-D", f"$fn={fn}", scad]
            if name == "cup":
                median, sd, cpu = hyperfine(" ".join(shlex.quote(a) for a in argv), args.runs,
                                            os.path.join(args.out, f"{name}_fn{fn}.json"))
                subprocess.run([args.openscad, "-o", dxf, "-D", f"$fn={fn}", scad], check=True,
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                dxf_area, _ = file_area(dxf)
                note = f"DXF area error {(dxf_area - exact) / exact:+.2e}"
            else:
                once = timed_once(argv, args.voids_timeout, os.path.join(args.out, f"{name}_fn{fn}.log"))
                if once is None:
                    rows.append((name, "OpenSCAD", f"$fn={fn}", None, None, None, None, None,
                                 f"did not finish in {args.voids_timeout} s"))
                    continue
                median, sd, cpu = once[0], 0.0, once[1]
                note = f"one run, max RSS {once[2]:.0f} MB"
            area, _ = file_area(svg)
            rows.append((name, "OpenSCAD", f"$fn={fn}", median, sd, cpu, area, (area - exact) / exact, note))
            print(f"{name} OpenSCAD $fn={fn}: {median:.3f} s, area error {(area - exact) / exact:+.2e}",
                  file=sys.stderr)
        if not have_kerf:
            continue
        for tolerance in args.tolerances.split(","):
            svg = os.path.join(args.out, f"{name}_kerf_{tolerance}.svg")
            argv = [args.kerf, "slice", kerf_model, "--plane", plane, "-o", svg,
                    "--tolerance", tolerance, "--stats"]
            median, sd, cpu = hyperfine(" ".join(shlex.quote(a) for a in argv), args.runs,
                                        os.path.join(args.out, f"{name}_kerf_{tolerance}.json"))
            with open(os.path.join(args.out, f"{name}_kerf_{tolerance}.stats"), "w") as log:
                subprocess.run(argv, stdout=log, stderr=subprocess.STDOUT, check=True)
            area, _ = file_area(svg)
            rows.append((name, "kerf", f"--tolerance {tolerance}", median, sd, cpu, area, (area - exact) / exact, ""))
            print(f"{name} kerf {tolerance}: {median:.3f} s, area error {(area - exact) / exact:+.2e}",
                  file=sys.stderr)

    print("| model | tool | setting | median s | sd s | CPU s | area error | ÷ OpenSCAD $fn=64 time | "
          "÷ OpenSCAD $fn=64 abs(error) | note |")
    print("|---|---|---|---:|---:|---:|---:|---:|---:|---|")
    for name in args.models.split(","):
        reference = [r for r in rows if r[0] == name and r[2] == "$fn=64" and r[3] is not None]
        for r in [r for r in rows if r[0] == name]:
            if r[3] is None:
                print(f"| {name} | {r[1]} | {r[2]} | — | — | — | — | — | — | {r[8]} |")
                continue
            ratio_t = ratio_e = "—"
            if reference:
                ratio_t = f"{r[3] / reference[0][3]:.3g}"
                ratio_e = f"{abs(r[7]) / abs(reference[0][7]):.2g}" if reference[0][7] else "—"
            print(f"| {name} | {r[1]} | {r[2]} | {r[3]:.4g} | {r[4]:.2g} | {r[5]:.4g} | {r[7]:+.2e} | "
                  f"{ratio_t} | {ratio_e} | {r[8]} |")
    print()
    for name in args.models.split(","):
        if any(r[0] == name for r in rows):
            print(f"- {name}: exact area {MODELS[name][4]} = {MODELS[name][3]!r}")


if __name__ == "__main__":
    main()
