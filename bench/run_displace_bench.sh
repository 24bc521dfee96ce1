#!/usr/bin/env bash
# The displacement benchmark of issue 10 §3 (docs/BENCHMARKS.md, "Displacement"): builds the
# checkers (hit_mask, displace_reference), writes the two displaced scenes, times kerf (default
# and --accel none) and POV-Ray's isosurface at two max_gradients, median of 3, and measures
# kerf's error against a long-double reference and POV-Ray's holes. About 5 minutes; prints
# a markdown table (the doc's subsection is written by hand from it).
#
#   bench/run_displace_bench.sh
#   bench/run_displace_bench.sh --runs 1 --scenes displace_noise     # a quick look
#
# Environment: KERF=path/to/kerf uses that executable instead of building one;
# BENCH_BUILD=dir is where the checkers are built (default build/bench-reference).
# Needs povray, python3, cmake and OpenImageIO's development files (libopenimageio-dev).
# Any arguments go to bench/displace_bench.py (see its --help).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/bench/bench_setup.sh"
bench_absolute_env
cd "$root"

bench_setup run_displace_bench.sh

bench_build="${BENCH_BUILD:-$root/build/bench-reference}"
cmake -S bench -B "$bench_build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$bench_build" --target hit_mask displace_reference -j"$(nproc)" >/dev/null
"$bench_build/hit_mask" --self-test   # the checkers check themselves before they judge anything
"$bench_build/displace_reference" --self-test

exec python3 bench/displace_bench.py --kerf "$KERF" --hit-mask "$bench_build/hit_mask" \
    --reference "$bench_build/displace_reference" "$@"
