#!/usr/bin/env python3
"""Time kerf against POV-Ray 3.7 on real scenes (POV-Ray samples translated to kerf).

scenes.txt lists `NAME  ORIGINAL` per line; ORIGINAL is relative to the Debian povray
package's examples directory (not copied into the repo). Both renderers run at one thread,
400x300, one sample per pixel (POV-Ray: -A, no antialiasing). Reports the median of N
alternating pairs of runs.
"""
import argparse, os, re, shutil, statistics, subprocess, sys, tempfile, time

HERE = os.path.dirname(os.path.abspath(__file__))
POV_EXAMPLES = "/usr/share/doc/povray/examples"


def read_scenes(path):
    scenes = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            name, orig = line.split()[:2]
            scenes.append((name, orig))
    return scenes


def run_pov(pov, orig, out):
    src = os.path.join(POV_EXAMPLES, orig)
    cmd = [pov, "+I" + os.path.basename(src), "+O" + out, "+W400", "+H300", "-A", "+WT1", "-D"]
    t0 = time.perf_counter()
    p = subprocess.run(cmd, cwd=os.path.dirname(src), capture_output=True, text=True)
    whole = time.perf_counter() - t0
    if p.returncode != 0:
        raise RuntimeError("povray failed on %s:\n%s" % (orig, p.stderr[-2000:]))
    m = re.search(r"Trace Time:\s+(\d+) hours?\s+(\d+) minutes?\s+(\d+) seconds?\s+\((\d+\.\d+) seconds\)", p.stderr)
    if m:
        trace = float(m.group(4))
    else:
        m = re.search(r"Trace Time:.*?\(([\d.]+) seconds\)", p.stderr)
        if not m:
            raise RuntimeError("no 'Trace Time:' in povray's output for %s" % orig)
        trace = float(m.group(1))
    return trace, whole


def run_kerf(kerf, name, out):
    cmd = [kerf, "render", os.path.join(HERE, name + ".kerf"), "-o", out, "--threads", "1",
           "--spp", "1", "--width", "400", "--height", "300", "--stats", "-q"]
    t0 = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True)
    whole = time.perf_counter() - t0
    if p.returncode != 0:
        raise RuntimeError("kerf failed on %s:\n%s" % (name, p.stderr[-2000:]))
    m = re.search(r"^\s*trace\s+([\d.eE+-]+)\s*s\s*$", p.stderr, re.M)
    if not m:
        raise RuntimeError("no 'trace' line in kerf's --stats for %s" % name)
    return float(m.group(1)), whole


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--kerf", default="/work/main/build/kerf")
    ap.add_argument("--povray", default="povray")
    ap.add_argument("--runs", type=int, default=3, help="alternating pairs per scene (median)")
    ap.add_argument("--only", default="", help="comma-separated scene names")
    ap.add_argument("--scenes", default=os.path.join(HERE, "scenes.txt"))
    a = ap.parse_args()

    pov = shutil.which(a.povray)
    if not pov:
        sys.exit("error: povray not found (install POV-Ray 3.7, e.g. apt-get install povray)")
    if not os.path.isdir(POV_EXAMPLES):
        sys.exit("error: %s missing (the povray-examples package provides it)" % POV_EXAMPLES)
    if not os.access(a.kerf, os.X_OK):
        sys.exit("error: kerf binary %s not found or not executable" % a.kerf)

    scenes = read_scenes(a.scenes)
    if a.only:
        want = set(a.only.split(","))
        unknown = want - {n for n, _ in scenes}
        if unknown:
            sys.exit("error: unknown scene(s): " + ", ".join(sorted(unknown)))
        scenes = [s for s in scenes if s[0] in want]

    tmp = tempfile.mkdtemp(prefix="kerf-real-bench-")
    rows, n_good, failed = [], 0, []
    for name, orig in scenes:
        pt, pw, kt, kw = [], [], [], []
        try:
            for _ in range(a.runs):
                t, w = run_pov(pov, orig, os.path.join(tmp, name + "_pov.png"))
                pt.append(t); pw.append(w)
                t, w = run_kerf(a.kerf, name, os.path.join(tmp, name + "_kerf.png"))
                kt.append(t); kw.append(w)
        except RuntimeError as e:
            print("warning: " + str(e), file=sys.stderr)
            failed.append(name)
            continue
        P, K = statistics.median(pt), statistics.median(kt)
        PW, KW = statistics.median(pw), statistics.median(kw)
        tr = K / P if P > 0 else float("inf")
        wr = KW / PW if PW > 0 else float("inf")
        if tr <= 0.5:
            n_good += 1
        rows.append((name, P, K, tr, PW, KW, wr))
        print("  %s done" % name, file=sys.stderr)

    print("| scene | POV trace s | kerf trace s | trace ratio | POV whole s | kerf whole s | whole ratio |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        print("| %s | %.3f | %.3f | %.2f | %.3f | %.3f | %.2f |" % r)
    print()
    print("%d of %d scenes at trace ratio <= 0.5%s" % (
        n_good, len(rows), (" (failed: %s)" % ", ".join(failed)) if failed else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
