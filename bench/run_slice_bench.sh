#!/usr/bin/env bash
# The slicing benchmark (issue 11 §5): OpenSCAD's projection(cut = true) against `kerf slice` on
# the classic cup (bench/slice/cup.{scad,kerf}) and the cube with 1000 spherical voids
# (bench/slice/voids.scad, models/voids.kerf), whole-process time (hyperfine, median of --runs)
# beside the area error against the closed form. Prints a Markdown table; writes only into
# OUT (default: a temporary folder, kept and named at the end). Skips the kerf rows when this
# kerf has no `slice` command yet. OpenSCAD is for this benchmark only:
# apt-get install -y openscad hyperfine.
#
#   bench/run_slice_bench.sh                       # cup at $fn 16-128, voids at $fn 16 (minutes)
#   bench/run_slice_bench.sh --voids-fn ''         # the cup alone
#   bench/run_slice_bench.sh --voids-fn 16,32 --voids-timeout 3600
#
# Environment: KERF=path/to/kerf (default build/kerf), OPENSCAD=path, OUT=folder.
# Any arguments go to bench/slice/slice_bench.py (see its --help).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench_setup.sh"
KERF="$(absolute "${KERF:-build/kerf}")"
OUT="$(absolute "${OUT:-$(mktemp -d /tmp/kerf-slice-bench.XXXXXX)}")"
cd "$(dirname "${BASH_SOURCE[0]}")/.."
for tool in "${OPENSCAD:-openscad}" hyperfine python3; do
    command -v "$tool" >/dev/null || { echo "run_slice_bench: '$tool' is missing (apt-get install $tool)" >&2; exit 1; }
done
[[ -x "$KERF" ]] || { echo "run_slice_bench: no kerf at $KERF (set KERF or build first)" >&2; exit 1; }
python3 bench/slice/slice_bench.py --kerf "$KERF" --openscad "${OPENSCAD:-openscad}" --out "$OUT" "$@"
echo "run_slice_bench: outputs and logs in $OUT" >&2
