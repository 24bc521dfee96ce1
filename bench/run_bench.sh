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
# Paths given in the environment are relative to the caller's directory.
absolute() { [[ "$1" = /* ]] && echo "$1" || echo "$PWD/$1"; }
if [[ -n "${KERF:-}" ]]; then KERF="$(absolute "$KERF")"; fi
if [[ -n "${BENCH_BUILD:-}" ]]; then BENCH_BUILD="$(absolute "$BENCH_BUILD")"; fi
cd "$root"

for tool in povray python3 cmake; do
    command -v "$tool" >/dev/null || { echo "run_bench.sh: '$tool' is missing (apt-get install $tool)" >&2; exit 1; }
done

if [[ -z "${KERF:-}" ]]; then
    if [[ -x scripts/build ]]; then
        scripts/build
    else
        cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
        cmake --build build --target kerf -j"$(nproc)"
    fi
    for candidate in build/kerf build/app/kerf; do
        if [[ -x "$candidate" ]]; then KERF="$candidate"; break; fi
    done
fi
[[ -x "${KERF:-}" ]] || { echo "run_bench.sh: no kerf executable (looked for build/kerf)" >&2; exit 1; }

bench_build="${BENCH_BUILD:-$root/build/bench-reference}"
cmake -S bench -B "$bench_build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$bench_build" -j"$(nproc)" >/dev/null
"$bench_build/depth_reference" --self-test   # the oracle checks itself before it judges kerf

python3 bench/gen_scenes.py
exec python3 bench/run_bench.py --kerf "$KERF" --reference "$bench_build/depth_reference" "$@"
