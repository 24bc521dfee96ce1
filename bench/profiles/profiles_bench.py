#!/usr/bin/env python3
"""Profiles in closed form against POV-Ray: trace and whole-process times at one thread,
400x300, POV-Ray -A against kerf --spp 1, median of N alternating pairs.

  python3 bench/profiles/profiles_bench.py [--kerf build/kerf] [--runs 5]

Scenes: lathe1a (POV-Ray's objects/lathe1a.pov against bench/real/lathe1a.kerf), goblet
(a lathe of lines and Béziers, bench/profiles/goblet.{pov,kerf}), text (extruded TrueType
text, bench/profiles/text.{pov,kerf}, the same font file)."""
import argparse, os, re, statistics, subprocess, sys, time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
EXAMPLES = "/usr/share/doc/povray/examples"
INCLUDE = "/usr/share/povray-3.7/include"
SCENES = [
    ("lathe1a", os.path.join(EXAMPLES, "objects/lathe1a.pov"), os.path.join(ROOT, "bench/real/lathe1a.kerf")),
    ("goblet", os.path.join(HERE, "goblet.pov"), os.path.join(HERE, "goblet.kerf")),
    ("text", os.path.join(HERE, "text.pov"), os.path.join(HERE, "text.kerf")),
]


def timed(cmd, cwd):
    start = time.perf_counter()
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    whole = time.perf_counter() - start
    if p.returncode != 0:
        sys.exit(f"profiles_bench: {' '.join(cmd)} failed:\n{p.stderr[-2000:]}")
    return p.stderr + p.stdout, whole


def povray(pov):
    out, whole = timed(["povray", f"+I{pov}", "+O/tmp/profiles_bench_pov.png", "+W400", "+H300",
                        "-A", "+WT1", "-D", f"+L{INCLUDE}"], os.path.dirname(pov))
    m = re.search(r"Trace Time:.*\(([\d.]+) seconds\)", out)
    return float(m.group(1)), whole


def kerf(binary, model):
    out, whole = timed([binary, "render", model, "-o", "/tmp/profiles_bench_kerf.png", "--threads", "1",
                        "--spp", "1", "--width", "400", "--height", "300", "--stats", "-q"], ROOT)
    m = re.search(r"^\s*trace\s+([\d.]+) s", out, re.M)
    return float(m.group(1)), whole


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--kerf", default=os.path.join(ROOT, "build/kerf"))
    ap.add_argument("--runs", type=int, default=5)
    args = ap.parse_args()
    if subprocess.run(["sh", "-c", "command -v povray"], capture_output=True).returncode != 0:
        sys.exit("profiles_bench: povray is missing (apt-get install povray povray-includes povray-examples)")
    print("| scene | POV-Ray trace s | kerf trace s | trace ratio | POV-Ray whole s | kerf whole s | whole ratio |")
    print("|---|---|---|---|---|---|---|")
    for name, pov, model in SCENES:
        p, k = [], []
        for _ in range(args.runs):
            p.append(povray(pov))
            k.append(kerf(args.kerf, model))
        pt, pw = statistics.median(x[0] for x in p), statistics.median(x[1] for x in p)
        kt, kw = statistics.median(x[0] for x in k), statistics.median(x[1] for x in k)
        print(f"| {name} | {pt:.3f} | {kt:.3f} | {kt / pt:.2f} | {pw:.2f} | {kw:.2f} | {kw / pw:.2f} |")


if __name__ == "__main__":
    main()
