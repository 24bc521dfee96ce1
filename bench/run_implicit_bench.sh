#!/usr/bin/env bash
# The implicit-surface benchmark of issue 8 (docs/BENCHMARKS.md, "Implicit surfaces"): builds
# the hit-mask checker, regenerates the scenes, renders gyroid, barth, blobs and cup with kerf
# (and POV-Ray's isosurface, and a baseline kerf for cup), median of 5, checks hit masks and
# POV-Ray's holes, and rewrites the implicit part of docs/BENCHMARKS.md. Takes 15-30 minutes.
#
#   bench/run_implicit_bench.sh --kerf-baseline /work/baseline-fe3036a/kerf \
#       --kerf-config default= none="--accel none" octree="--accel octree"
#   bench/run_implicit_bench.sh --runs 1 --scenes gyroid barth     # a quick look; doc untouched
#
# Environment: KERF=path/to/kerf uses that executable instead of building one;
# BENCH_BUILD=dir is where the checker is built (default build/bench-reference).
# Needs povray, python3, cmake and OpenImageIO's development files (libopenimageio-dev).
# Any arguments go to bench/implicit_bench.py (see its --help).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/bench/bench_setup.sh"
bench_absolute_env
# Arguments that name files are relative to the caller's directory too.
args=()
for arg in "$@"; do
    if [[ "${previous:-}" = --kerf-baseline ]]; then arg="$(absolute "$arg")"; fi
    args+=("$arg"); previous="$arg"
done
cd "$root"

bench_setup run_implicit_bench.sh

bench_build="${BENCH_BUILD:-$root/build/bench-reference}"
cmake -S bench -B "$bench_build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$bench_build" --target hit_mask -j"$(nproc)" >/dev/null
"$bench_build/hit_mask" --self-test   # the checker checks itself before it judges anything

python3 bench/gen_implicit_scenes.py
exec python3 bench/implicit_bench.py --kerf "$KERF" --hit-mask "$bench_build/hit_mask" ${args[@]+"${args[@]}"}
