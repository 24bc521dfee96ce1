#!/usr/bin/env bash
# The noise benchmark of issue 10 §4 (docs/BENCHMARKS.md, "Noise against time"): regenerates
# the noise scenes, renders each sampler at 4-256 spp against a 4096-spp kerf reference, times
# kerf and POV-Ray at equal RMSE on the soft-shadow and depth-of-field scenes (median of 3),
# and rewrites the noise section at the end of docs/BENCHMARKS.md. About 10-15 minutes.
#
#   bench/run_noise_bench.sh
#   bench/run_noise_bench.sh --quick          # 64 x 48, small references: a look; doc untouched
#
# Environment: KERF=path/to/kerf uses that executable instead of building one.
# Needs povray, python3 and oiiotool (OpenImageIO's tools read the EXR images).
# Any arguments go to bench/noise_bench.py (see its --help).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [[ -n "${KERF:-}" && "$KERF" != /* ]]; then KERF="$PWD/$KERF"; fi
cd "$root"

source bench/bench_setup.sh
bench_setup run_noise_bench.sh
command -v oiiotool >/dev/null || {
    echo "run_noise_bench.sh: 'oiiotool' is missing (apt-get install openimageio-tools)" >&2
    exit 1
}

python3 bench/gen_noise_scenes.py
exec python3 bench/noise_bench.py --kerf "$KERF" "$@"
