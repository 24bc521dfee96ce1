#!/usr/bin/env bash
# The bricked-storage benchmark of issue 14 §1 (docs/BENCHMARKS.md, "Bricked storage"): builds
# kerf_brick_bench (bench/CMakeLists.txt, which adds kerf's volume
# library) and runs it: a 512³ float field as a flat x-fastest array, a BrickGrid and an
# OpenVDB FloatGrid read through a ValueAccessor, in one process (1.6 GiB: three copies). About
# 5 minutes on this 2-core machine. Prints a markdown table and writes it, with the machine's
# caches and load, to bench/out/brick_bench.md.
#
#   bench/run_brick_bench.sh
#   bench/run_brick_bench.sh --size 256 --runs 1      # a quick look
#
# Environment: BENCH_BUILD=dir is where the benchmark is built (default build/bench-reference).
# Arguments go to kerf_brick_bench: [--size N] [--runs R] [--rays K] [--points K] [--slices K]
# [--brick B] [--macro M] [--only WORKLOAD] [--ahead-flat V] [--ahead-brick V] [--camera P].
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/bench/bench_setup.sh"
bench_absolute_env
cd "$root"

command -v cmake >/dev/null || { echo "run_brick_bench.sh: 'cmake' is missing (apt-get install cmake)" >&2; exit 1; }
bench_build="${BENCH_BUILD:-$root/build/bench-reference}"
mkdir -p bench/out
# The configure's chatter (kerf's dependencies) goes to a log, shown only when it fails.
cmake -S bench -B "$bench_build" -DCMAKE_BUILD_TYPE=Release >bench/out/configure.log 2>&1 ||
    { cat bench/out/configure.log >&2; exit 1; }
cmake --build "$bench_build" --target kerf_brick_bench -j"$(nproc)" >/dev/null

out=bench/out/brick_bench.md
trap 'rm -f "$out.tmp"' EXIT
# Written whole or not at all: into a temporary file, renamed when the run has finished.
{
    echo "Command: bench/run_brick_bench.sh $*"
    echo "Machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) CPUs; caches:" \
        "$(lscpu | grep -E '^L[123]' | sed 's/  */ /g' | paste -sd ';' -)"
    echo "Load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
    echo
    "$bench_build/kerf_brick_bench" "$@"
    echo
    echo "Load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
} | tee "$out.tmp"
mv "$out.tmp" "$out"
echo "run_brick_bench.sh: written $out"
