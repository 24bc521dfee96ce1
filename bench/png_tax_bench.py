#!/usr/bin/env python3
"""Issue 25 §4: what writing a PNG costs on top of compiling the model.

Times `kerf check M` and `kerf render M -o out.png` of a 1×1 model (one sphere, one light),
interleaved run by run, for this kerf and optionally another (--before, e.g. a build from
before PNGs were encoded by kerf itself), and prints the medians and the render's excess over
check as a Markdown table. Wall time of whole processes, `--runs` of each (default 21).

    bench/png_tax_bench.py [--kerf build/kerf] [--before /path/to/old/kerf] [--runs 21]
"""
import argparse
import os
import statistics
import subprocess
import tempfile
import time

MODEL = """object sphere { center <0, 0, 0> radius 1 };
camera { eye <0, 0, -4> look_at <0, 0, 0> fov 40 }
light point { at <5, 8, -5> color <1, 1, 1> power 300 }
render { width 1 height 1 spp 1 }
"""


def wall(cmd, cwd):
    start = time.perf_counter()
    subprocess.run(cmd, cwd=cwd, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--kerf", default="build/kerf")
    ap.add_argument("--before")
    ap.add_argument("--runs", type=int, default=21)
    args = ap.parse_args()
    kerfs = {"this kerf": os.path.abspath(args.kerf)}
    if args.before:
        kerfs["before"] = os.path.abspath(args.before)
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "one.kerf"), "w") as f:
            f.write(MODEL)
        times = {(k, c): [] for k in kerfs for c in ("check", "render")}
        for _ in range(args.runs):
            for name, kerf in kerfs.items():
                times[(name, "check")].append(wall([kerf, "check", "-q", "one.kerf"], d))
                times[(name, "render")].append(
                    wall([kerf, "render", "-q", "one.kerf", "-o", "one.png"], d))
    print("| kerf | `check` median | `render -o one.png` median | render − check |")
    print("|---|---:|---:|---:|")
    for name in kerfs:
        c = statistics.median(times[(name, "check")]) * 1e3
        r = statistics.median(times[(name, "render")]) * 1e3
        print(f"| {name} | {c:.1f} ms | {r:.1f} ms | {r - c:.1f} ms |")


if __name__ == "__main__":
    main()
