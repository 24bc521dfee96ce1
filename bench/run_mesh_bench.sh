#!/usr/bin/env bash
# The Embree comparison of issue 12 §3 (docs/BENCHMARKS.md, "Meshes against Embree"): writes
# the three meshes (bench/gen_bench_meshes.py), builds kerf_embree_bench (bench/CMakeLists.txt,
# which adds kerf's mesh library), and runs it on the bumpy sphere, the city and the fan. About
# 3 minutes on this 2-core machine. Prints markdown tables (kerf against Embree in the same
# process, the ratios, the agreement figures) and writes them to bench/out/embree_bench.md.
#
#   bench/run_mesh_bench.sh
#   bench/run_mesh_bench.sh --runs 1 --build-runs 1 --size 256    # a quick look
#
# Environment: BENCH_BUILD=dir is where the benchmark is built (default build/bench-reference);
# MESHES=dir is where the meshes are written (default bench/out/meshes).
# Needs python3, cmake, Embree 3 (apt-get install libembree-dev: a bench-only peer, not in
# scripts/install-deps) and kerf's own dependencies. Arguments go to kerf_embree_bench:
# [--size N] [--fan-size N] [--runs R] [--build-runs R] [--robust].
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/bench/bench_setup.sh"
bench_absolute_env
meshes="$(absolute "${MESHES:-$root/bench/out/meshes}")"
cd "$root"

for tool in python3 cmake; do
    command -v "$tool" >/dev/null || { echo "run_mesh_bench.sh: '$tool' is missing (apt-get install $tool)" >&2; exit 1; }
done
bench_build="${BENCH_BUILD:-$root/build/bench-reference}"
mkdir -p bench/out
# The configure's chatter (kerf's dependencies) goes to a log, shown only when it fails.
cmake -S bench -B "$bench_build" -DCMAKE_BUILD_TYPE=Release >bench/out/configure.log 2>&1 ||
    { cat bench/out/configure.log >&2; exit 1; }
if ! grep -q '^embree_DIR:PATH=/' "$bench_build/CMakeCache.txt"; then
    echo "run_mesh_bench.sh: Embree 3 was not found (apt-get install libembree-dev)" >&2
    exit 1
fi
cmake --build "$bench_build" --target kerf_embree_bench -j"$(nproc)" >/dev/null

python3 bench/gen_bench_meshes.py "$meshes"
out=bench/out/embree_bench.md
trap 'rm -f "$out.tmp"' EXIT
# Written whole or not at all: into a temporary file, renamed when the run has finished.
"$bench_build/kerf_embree_bench" "$@" "$meshes/sphere.ply" "$meshes/city.ply" "$meshes/fan.ply" \
    | tee "$out.tmp"
mv "$out.tmp" "$out"
echo "run_mesh_bench.sh: written $out"
