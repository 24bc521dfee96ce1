#!/usr/bin/env bash
# The kerf / POV-Ray benchmark: builds kerf (Release) and the depth oracle, regenerates the
# scenes, renders each one with both renderers (800 x 600, 1 sample per pixel, 2 threads,
# median of 5, alternating), checks kerf's depth against the long-double oracle, and rewrites
# the generated part of docs/BENCHMARKS.md. Callable from any directory; takes ~5-15 minutes.
#
#   bench/run_bench.sh                    # everything
#   bench/run_bench.sh --runs 1 --scenes cup tori   # a quick look; only a full run rewrites the doc
#
# Environment: KERF=path/to/kerf uses that executable instead of building one;
# BENCH_BUILD=dir is where the oracle is built (default build/bench-reference).
# Any arguments go to bench/run_bench.py (see its --help).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/bench/bench_setup.sh"
bench_absolute_env
cd "$root"

bench_setup run_bench.sh

bench_build="${BENCH_BUILD:-$root/build/bench-reference}"
cmake -S bench -B "$bench_build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$bench_build" -j"$(nproc)" >/dev/null
"$bench_build/depth_reference" --self-test   # the oracle checks itself before it judges kerf

python3 bench/gen_scenes.py
exec python3 bench/run_bench.py --kerf "$KERF" --reference "$bench_build/depth_reference" "$@"
