#!/usr/bin/env bash
# The level-set comparison of issue 14 §3 (docs/BENCHMARKS.md, "Level sets against OpenVDB"):
# builds kerf_vdb_ray_bench (bench/CMakeLists.txt, which adds kerf's volume library), writes a
# 517³-voxel sphere level set and a torus with OpenVDB, and traces the same rays with kerf's
# volume solid and OpenVDB's LevelSetRayIntersector on one thread, median of 5 runs. Prints a
# markdown table and writes it to bench/out/vdb_bench.md.
#
#   bench/run_vdb_bench.sh
#   bench/run_vdb_bench.sh --runs 1 --size 256    # a quick look
#
# Environment: BENCH_BUILD=dir is where the benchmark is built (default build/bench-reference).
# Arguments go to kerf_vdb_ray_bench: [--size N] [--runs R] [--radius-voxels V] [--out DIR].
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/bench/bench_setup.sh"
bench_absolute_env
cd "$root"
command -v cmake >/dev/null || { echo "run_vdb_bench.sh: 'cmake' is missing (apt-get install cmake)" >&2; exit 1; }
bench_build="${BENCH_BUILD:-$root/build/bench-reference}"
mkdir -p bench/out
cmake -S bench -B "$bench_build" -DCMAKE_BUILD_TYPE=Release >bench/out/configure.log 2>&1 ||
    { cat bench/out/configure.log >&2; exit 1; }
cmake --build "$bench_build" --target kerf_vdb_ray_bench -j"$(nproc)" >/dev/null
out=bench/out/vdb_bench.md
trap 'rm -f "$out.tmp"' EXIT
# Written whole or not at all: into a temporary file, renamed when the run has finished.
"$bench_build/kerf_vdb_ray_bench" --out bench/out/vdb "$@" | tee "$out.tmp"
mv "$out.tmp" "$out"
