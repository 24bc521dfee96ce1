#!/usr/bin/env bash
# Parallel efficiency of the MPI driver (issue 15 §3): one model rendered by kerf render with
# 1 and 2 threads and by kerf-mpi with 1 rank x 2 threads and 2 ranks x 1 thread, whole-process
# wall time (start-up, compile and acceleration included: each rank does them), median of
# RUNS. Every image is compared with the 1-thread kerf render bit for bit (the max |difference|
# column; 0 means identical). The bytes gathered per tile and the tiles per rank come from
# kerf-mpi --stats. Prints a Markdown table; writes only into OUT (default: a temporary folder).
#
#   bench/run_mpi_bench.sh                     # models/cup.kerf at 480x360, spp 4, box filter
#   MODEL=models/glass.kerf ARGS="--spp 8 --filter gaussian" bench/run_mpi_bench.sh
#
# Environment: KERF, KERF_MPI (default build/kerf, build/kerf-mpi), MPIRUN (default mpirun),
# MODEL, ARGS (render options), RUNS (default 3), OUT.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench_setup.sh"
KERF="$(absolute "${KERF:-build/kerf}")"
KERF_MPI="$(absolute "${KERF_MPI:-build/kerf-mpi}")"
MODEL="$(absolute "${MODEL:-models/cup.kerf}")"
ARGS="${ARGS:---width 480 --height 360 --spp 4}"
RUNS="${RUNS:-3}"
OUT="$(absolute "${OUT:-$(mktemp -d /tmp/kerf-mpi-bench.XXXXXX)}")"
MPIRUN="${MPIRUN:-mpirun}"
mkdir -p "$OUT"
for tool in "$MPIRUN" oiiotool python3; do
    command -v "$tool" >/dev/null || { echo "run_mpi_bench: '$tool' is missing" >&2; exit 1; }
done
for exe in "$KERF" "$KERF_MPI"; do
    [[ -x "$exe" ]] || { echo "run_mpi_bench: no executable at $exe (build kerf and kerf-mpi)" >&2; exit 1; }
done
ROOT=""
[[ "$(id -u)" = 0 ]] && ROOT="--allow-run-as-root"

# seconds NAME COMMAND…: runs COMMAND RUNS times, prints the median wall time in seconds.
seconds() {
    local name="$1"; shift
    local times=()
    for _ in $(seq "$RUNS"); do
        local t0 t1
        t0=$(date +%s.%N)
        "$@" >"$OUT/$name.log" 2>&1 || { echo "run_mpi_bench: $name failed, see $OUT/$name.log" >&2; exit 1; }
        t1=$(date +%s.%N)
        times+=("$(python3 -c "print($t1 - $t0)")")
    done
    python3 -c "import statistics, sys; print(f'{statistics.median(map(float, sys.argv[1:])):.3f}')" "${times[@]}"
}

# maxdiff A B: the largest absolute difference of two images' values (0: identical).
maxdiff() {
    [[ -f "$1" && -f "$2" ]] || { echo "no image"; return; }
    oiiotool "$1" "$2" --diff --fail 0 --failpercent 0 --hardfail 0 2>&1 |
        awk '/Max error/ {print $4; found=1} /^PASS/ {pass=1} END {if (!found) print (pass ? 0 : "?")}'
}

# shellcheck disable=SC2086
t11=$(seconds k1 "$KERF" render "$MODEL" -q $ARGS --threads 1 -o "$OUT/k1.exr")
# shellcheck disable=SC2086
t12=$(seconds k2 "$KERF" render "$MODEL" -q $ARGS --threads 2 -o "$OUT/k2.exr")
# shellcheck disable=SC2086
tm12=$(seconds m12 "$MPIRUN" $ROOT -n 1 "$KERF_MPI" render "$MODEL" -q $ARGS --threads 2 \
    -o "$OUT/m12.exr" --stats)
# shellcheck disable=SC2086
tm21=$(seconds m21 "$MPIRUN" $ROOT -n 2 --oversubscribe "$KERF_MPI" render "$MODEL" -q $ARGS \
    --threads 1 -o "$OUT/m21.exr" --stats)

echo "model: $MODEL $ARGS; median of $RUNS runs; $(nproc) cores"
echo
echo "| run | ranks x threads | wall s | speed-up vs 1x1 | efficiency | max abs difference vs 1x1 |"
echo "|---|---|---|---|---|---|"
row() {
    python3 -c "
import sys
name, shape, t, t1, workers, diff = sys.argv[1:]
t, t1, workers = float(t), float(t1), int(workers)
print(f'| {name} | {shape} | {t:.2f} | {t1 / t:.2f} | {t1 / t / workers:.0%} | {diff} |')" "$@"
}
row "kerf render" "1 x 1" "$t11" "$t11" 1 0
row "kerf render" "1 x 2" "$t12" "$t11" 2 "$(maxdiff "$OUT/k1.exr" "$OUT/k2.exr")"
row "kerf-mpi render" "1 x 2" "$tm12" "$t11" 2 "$(maxdiff "$OUT/k1.exr" "$OUT/m12.exr")"
row "kerf-mpi render" "2 x 1" "$tm21" "$t11" 2 "$(maxdiff "$OUT/k1.exr" "$OUT/m21.exr")"
echo
echo "2 ranks x 1 thread against 1 rank x 2 threads (kerf render): $(python3 -c "print(f'{$t12 / $tm21:.0%}')") of its speed"
grep -h "kerf-mpi:" "$OUT/m21.log" | sed 's/^/2 ranks: /'
grep -h "^  trace\|trace  " "$OUT/m21.log" | head -2 | sed 's/^/2 ranks, rank 0: /'
echo "run_mpi_bench: outputs and logs in $OUT" >&2
